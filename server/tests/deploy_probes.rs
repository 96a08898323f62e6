//! The Kubernetes Deployment's probes, mimicked: the server started from the container's own
//! command line in deploy/kubernetes/server.yaml (its args and environment; the Secrets' tokens
//! and TLS files made for the test, the ports free ones), bound beyond loopback, and probed as
//! the kubelet's gRPC probe does: a plaintext `grpc.health.v1.Health/Check` on the probe's port
//! and service, until the startup probe's budget runs out. The same command line without the
//! tokens must refuse to start: the non-loopback bind works because they are set.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use serde_norway::Value;
use tonic_health::pb::HealthCheckRequest;
use tonic_health::pb::health_check_response::ServingStatus;
use tonic_health::pb::health_client::HealthClient;

const BIN: &str = env!("CARGO_BIN_EXE_foveal-server");

/// The container of the Deployment in deploy/kubernetes/server.yaml.
fn container() -> Value {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../deploy/kubernetes/server.yaml");
    let text = std::fs::read_to_string(&path).expect("server.yaml");
    for doc in serde_norway::Deserializer::from_str(&text) {
        let v: Value = serde::Deserialize::deserialize(doc).expect("YAML");
        if v["kind"].as_str() == Some("Deployment") {
            let containers = &v["spec"]["template"]["spec"]["containers"];
            return containers[0].clone();
        }
    }
    panic!("no Deployment in {}", path.display());
}

fn volumes() -> Value {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../deploy/kubernetes/server.yaml");
    let text = std::fs::read_to_string(&path).expect("server.yaml");
    for doc in serde_norway::Deserializer::from_str(&text) {
        let v: Value = serde::Deserialize::deserialize(doc).expect("YAML");
        if v["kind"].as_str() == Some("Deployment") {
            return v["spec"]["template"]["spec"]["volumes"].clone();
        }
    }
    Value::Null
}

fn free_port() -> u16 {
    let l = std::net::TcpListener::bind("0.0.0.0:0").expect("a free port");
    l.local_addr().expect("addr").port()
}

fn port_of(addr: &str) -> u16 {
    addr.rsplit_once(':')
        .and_then(|(_, p)| p.parse().ok())
        .unwrap_or_else(|| panic!("{addr}: no port"))
}

/// What the kubelet would run: the args, and the environment with each Secret's key filled (the
/// tokens made here) and each Secret volume's files written under `root`, the addresses' ports
/// swapped for free ones (`ports` maps the manifest's to them).
struct CommandLine {
    args: Vec<String>,
    env: BTreeMap<String, String>,
    ports: BTreeMap<u16, u16>,
}

fn command_line(root: &Path, with_secrets: bool) -> CommandLine {
    let c = container();
    let ca = foveal_tests::TestCa::new();
    // Secret volumes: the TLS pair, as `kubectl create secret tls` names its keys.
    let mut mounts: Vec<(String, PathBuf)> = Vec::new();
    let vols = volumes();
    for m in c["volumeMounts"].as_sequence().into_iter().flatten() {
        let (name, at) = (
            m["name"].as_str().expect("name"),
            m["mountPath"].as_str().expect("path"),
        );
        let secret = vols
            .as_sequence()
            .into_iter()
            .flatten()
            .find(|v| v["name"].as_str() == Some(name))
            .and_then(|v| v["secret"]["secretName"].as_str());
        if secret.is_some() {
            let dir = root.join(name);
            std::fs::create_dir_all(&dir).expect("dir");
            std::fs::write(dir.join("tls.crt"), &ca.cert_pem).expect("cert");
            std::fs::write(dir.join("tls.key"), &ca.key_pem).expect("key");
            mounts.push((at.to_owned(), dir));
        }
    }
    let mut env = BTreeMap::new();
    let mut ports = BTreeMap::new();
    for (k, e) in c["env"].as_sequence().into_iter().flatten().enumerate() {
        let name = e["name"].as_str().expect("env name").to_owned();
        if let Some(v) = e["value"].as_str() {
            let mut v = v.to_owned();
            for (at, dir) in &mounts {
                if let Some(rest) = v.strip_prefix(at.as_str()) {
                    v = format!("{}{rest}", dir.display());
                }
            }
            if name.ends_with("_ADDR") {
                let port = port_of(&v);
                let free = free_port();
                ports.insert(port, free);
                v = format!("{}:{free}", v.rsplit_once(':').map_or("", |(h, _)| h));
            }
            env.insert(name, v);
        } else if e["valueFrom"]["secretKeyRef"].is_mapping() {
            if with_secrets {
                env.insert(name, format!("probe-test-token-{k:02}-0123456789abcdef"));
            }
        } else {
            panic!("{name}: neither a value nor a Secret's key");
        }
    }
    let args = c["args"]
        .as_sequence()
        .into_iter()
        .flatten()
        .map(|a| a.as_str().expect("arg").to_owned())
        .collect();
    CommandLine { args, env, ports }
}

fn start(cl: &CommandLine) -> Child {
    let mut cmd = Command::new(BIN);
    cmd.args(&cl.args)
        .stdout(Stdio::null())
        .stderr(Stdio::piped());
    // Only the manifest's environment reaches the server's flags.
    for (k, _) in std::env::vars() {
        if k.starts_with("FOVEAL_") {
            cmd.env_remove(k);
        }
    }
    cmd.envs(&cl.env);
    cmd.spawn().expect("foveal-server starts")
}

/// One probe as the kubelet makes it: a plaintext Check within the probe's timeout.
async fn probe(port: u16, service: &str, timeout: Duration) -> Option<i32> {
    let call = async {
        let channel = tonic::transport::Endpoint::from_shared(format!("http://127.0.0.1:{port}"))
            .ok()?
            .connect()
            .await
            .ok()?;
        let mut client = HealthClient::new(channel);
        let req = HealthCheckRequest {
            service: service.to_owned(),
        };
        client.check(req).await.ok().map(|r| r.into_inner().status)
    };
    tokio::time::timeout(timeout, call).await.ok().flatten()
}

struct Probe {
    port: u16,
    service: String,
    period: Duration,
    timeout: Duration,
    failures: u32,
}

fn probe_of(c: &Value, which: &str, ports: &BTreeMap<u16, u16>) -> Probe {
    let p = &c[which];
    let port = p["grpc"]["port"]
        .as_u64()
        .unwrap_or_else(|| panic!("{which}: no gRPC port"));
    let port = u16::try_from(port).expect("port");
    let secs = |k: &str, default: u64| Duration::from_secs(p[k].as_u64().unwrap_or(default));
    Probe {
        port: *ports
            .get(&port)
            .unwrap_or_else(|| panic!("{which}: port {port} is no address's")),
        service: p["grpc"]["service"].as_str().unwrap_or("").to_owned(),
        period: secs("periodSeconds", 10),
        timeout: secs("timeoutSeconds", 1),
        failures: u32::try_from(p["failureThreshold"].as_u64().unwrap_or(3)).expect("threshold"),
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_deployments_probes_pass_on_its_command_line() {
    let root = std::env::temp_dir().join(format!("foveal-probes-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&root);
    let cl = command_line(&root, true);
    assert!(
        cl.env
            .get("FOVEAL_ADDR")
            .is_some_and(|a| a.starts_with("0.0.0.0:")),
        "{:?}: the manifest binds beyond loopback",
        cl.env.get("FOVEAL_ADDR")
    );
    let c = container();
    let startup = probe_of(&c, "startupProbe", &cl.ports);
    let mut server = start(&cl);
    // The startup probe: every period until SERVING, at most its failure threshold.
    let started = Instant::now();
    let mut status = None;
    for _ in 0..startup.failures {
        status = probe(startup.port, &startup.service, startup.timeout).await;
        if status == Some(ServingStatus::Serving as i32) {
            break;
        }
        if let Ok(Some(exit)) = server.try_wait() {
            let mut err = String::new();
            if let Some(mut e) = server.stderr.take() {
                let _ = std::io::Read::read_to_string(&mut e, &mut err);
            }
            panic!("the server exited ({exit}) before its probes passed:\n{err}");
        }
        tokio::time::sleep(startup.period.min(Duration::from_millis(500))).await;
    }
    assert_eq!(
        status,
        Some(ServingStatus::Serving as i32),
        "startup probe not SERVING after {:?}",
        started.elapsed()
    );
    for which in ["livenessProbe", "readinessProbe"] {
        let p = probe_of(&c, which, &cl.ports);
        assert_eq!(
            probe(p.port, &p.service, p.timeout).await,
            Some(ServingStatus::Serving as i32),
            "{which} (service {:?})",
            p.service
        );
    }
    // The main port speaks TLS only: a plaintext call there gets no answer.
    let main = cl.ports[&port_of(
        &container()["env"]
            .as_sequence()
            .into_iter()
            .flatten()
            .find(|e| e["name"].as_str() == Some("FOVEAL_ADDR"))
            .and_then(|e| e["value"].as_str().map(str::to_owned))
            .expect("FOVEAL_ADDR"),
    )];
    assert_eq!(probe(main, "", Duration::from_secs(2)).await, None);
    let _ = server.kill();
    let _ = server.wait();

    // Without the Secrets' tokens the same command line refuses the non-loopback bind.
    let bare = command_line(&root.join("bare"), false);
    let out = Command::new(BIN)
        .args(&bare.args)
        .envs(&bare.env)
        .env_remove("FOVEAL_VIEWER_TOKEN")
        .env_remove("FOVEAL_GAZE_TOKEN")
        .env_remove("FOVEAL_ADMIN_TOKEN")
        .env_remove("FOVEAL_TOKENS")
        .env_remove("FOVEAL_INSECURE")
        .stdout(Stdio::null())
        .output()
        .expect("runs");
    assert!(
        !out.status.success(),
        "served beyond loopback without tokens"
    );
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("token"), "{err}");
    let _ = std::fs::remove_dir_all(&root);
}
