//! Every manifest under deploy/kubernetes decoded strictly against the Kubernetes API types (v1.33):
//! a field the API does not have, a value of the wrong type or a wrong apiVersion/kind fails, as
//! the API server would refuse it. Then what the types cannot see: the manifests agree with each
//! other (the shards' count and volume, the probes' port), and the Slurm array runs the
//! Kubernetes Job's protocol.

use std::path::{Path, PathBuf};

use k8s_openapi::api::apps::v1::Deployment;
use k8s_openapi::api::batch::v1::Job;
use k8s_openapi::api::core::v1::{Container, PersistentVolumeClaim, Service};
use serde::de::DeserializeOwned;

fn deploy_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).to_owned()
}

/// One decoded document.
#[derive(Debug)]
enum Object {
    Deployment(Box<Deployment>),
    Service(Box<Service>),
    Job(Box<Job>),
    Claim(Box<PersistentVolumeClaim>),
}

/// Decode `doc` as `T`, refusing any field `T` does not have (the types themselves ignore them).
fn strict<T: DeserializeOwned>(doc: serde_norway::Value, what: &str) -> T {
    let mut unknown = Vec::new();
    let value: T = serde_ignored::deserialize(doc, |path| unknown.push(path.to_string()))
        .unwrap_or_else(|e| panic!("{what}: {e}"));
    assert!(
        unknown.is_empty(),
        "{what}: fields the API does not have: {unknown:?}"
    );
    value
}

/// Every document of one manifest file, decoded by its kind.
fn decode(path: &Path) -> Vec<Object> {
    let text = std::fs::read_to_string(path).expect("manifest readable");
    let mut out = Vec::new();
    for (k, doc) in serde_norway::Deserializer::from_str(&text).enumerate() {
        let value: serde_norway::Value = serde::Deserialize::deserialize(doc)
            .unwrap_or_else(|e| panic!("{} document {k}: not YAML: {e}", path.display()));
        if value.is_null() {
            continue;
        }
        let kind = value
            .get("kind")
            .and_then(serde_norway::Value::as_str)
            .unwrap_or_default()
            .to_owned();
        let what = format!("{} document {k} ({kind})", path.display());
        out.push(match kind.as_str() {
            "Deployment" => Object::Deployment(Box::new(strict(value, &what))),
            "Service" => Object::Service(Box::new(strict(value, &what))),
            "Job" => Object::Job(Box::new(strict(value, &what))),
            "PersistentVolumeClaim" => Object::Claim(Box::new(strict(value, &what))),
            other => panic!("{what}: kind {other:?} is not one these tests know"),
        });
    }
    out
}

fn manifests() -> Vec<(String, Vec<Object>)> {
    let dir = deploy_dir().join("kubernetes");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .expect("deploy/kubernetes")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "yaml"))
        .collect();
    files.sort();
    files
        .iter()
        .map(|p| {
            let name = p.file_name().map(|n| n.to_string_lossy().into_owned());
            (name.unwrap_or_default(), decode(p))
        })
        .collect()
}

fn job(all: &[(String, Vec<Object>)], name: &str) -> Job {
    all.iter()
        .flat_map(|(_, objs)| objs)
        .find_map(|o| match o {
            Object::Job(j) if j.metadata.name.as_deref() == Some(name) => Some((**j).clone()),
            _ => None,
        })
        .unwrap_or_else(|| panic!("no Job {name}"))
}

fn container(spec: &Option<k8s_openapi::api::core::v1::PodSpec>) -> Container {
    let spec = spec.as_ref().expect("pod spec");
    assert_eq!(spec.containers.len(), 1, "one container per pod");
    spec.containers[0].clone()
}

fn env(c: &Container, name: &str) -> Option<String> {
    c.env
        .iter()
        .flatten()
        .find(|e| e.name == name)
        .and_then(|e| e.value.clone())
}

#[test]
fn every_manifest_decodes_strictly() {
    let all = manifests();
    let kinds: Vec<&str> = all
        .iter()
        .flat_map(|(_, objs)| objs)
        .map(|o| match o {
            Object::Deployment(_) => "Deployment",
            Object::Service(_) => "Service",
            Object::Job(_) => "Job",
            Object::Claim(_) => "PersistentVolumeClaim",
        })
        .collect();
    for k in ["Deployment", "Service", "Job", "PersistentVolumeClaim"] {
        assert!(kinds.contains(&k), "no {k} among {kinds:?}");
    }
}

#[test]
fn a_misspelt_field_or_a_wrong_type_is_refused() {
    let good = "apiVersion: batch/v1\nkind: Job\nmetadata:\n  name: x\nspec:\n  completions: 2\n  \
                template:\n    spec:\n      containers: [{name: a, image: b}]\n";
    let doc: serde_norway::Value = serde_norway::from_str(good).expect("yaml");
    let _: Job = strict(doc, "good");
    for bad in [
        good.replace("completions", "completion"),
        good.replace("completions: 2", "completions: two"),
        good.replace("batch/v1", "batch/v2"),
    ] {
        let doc: serde_norway::Value = serde_norway::from_str(&bad).expect("yaml");
        let refused = std::panic::catch_unwind(|| {
            let _: Job = strict(doc, "bad");
        });
        assert!(refused.is_err(), "accepted:\n{bad}");
    }
}

#[test]
fn the_study_job_is_indexed_over_one_volume_and_merged_from_it() {
    let all = manifests();
    let study = job(&all, "foveal-study");
    let spec = study.spec.as_ref().expect("job spec");
    assert_eq!(spec.completion_mode.as_deref(), Some("Indexed"));
    let completions = spec.completions.expect("completions");
    assert!(spec.parallelism.is_some_and(|p| p >= 1 && p <= completions));
    let shard = container(&study.spec.as_ref().expect("spec").template.spec);
    // The shard count the binary reads is the Job's.
    assert_eq!(env(&shard, "FOVEAL_SHARDS"), Some(completions.to_string()));
    let args = shard.args.clone().unwrap_or_default();
    assert_eq!(
        shard.command.as_deref(),
        Some(&["foveal-bench".to_string()][..])
    );
    assert_eq!(args.first().map(String::as_str), Some("study"));
    assert!(
        !args.iter().any(|a| a.starts_with("--shard")),
        "{args:?}: index from the Job"
    );
    let out = args
        .iter()
        .position(|a| a == "--out")
        .and_then(|k| args.get(k + 1))
        .expect("--out");
    let merge = container(
        &job(&all, "foveal-study-merge")
            .spec
            .expect("spec")
            .template
            .spec,
    );
    let margs = merge.args.clone().unwrap_or_default();
    assert_eq!(margs.first().map(String::as_str), Some("merge"));
    assert_eq!(
        margs.get(1),
        Some(out),
        "the merge reads where the shards write"
    );
    // Both on the one ReadWriteMany claim, mounted where they write.
    let claim = all
        .iter()
        .flat_map(|(_, objs)| objs)
        .find_map(|o| match o {
            Object::Claim(c) => Some(c.clone()),
            _ => None,
        })
        .expect("claim");
    let access = claim.spec.as_ref().and_then(|s| s.access_modes.clone());
    assert_eq!(access, Some(vec!["ReadWriteMany".to_string()]));
    let claim_name = claim.metadata.name.clone().expect("claim name");
    for (j, c) in [("foveal-study", &shard), ("foveal-study-merge", &merge)] {
        let pod = job(&all, j).spec.expect("spec").template.spec.expect("pod");
        let vol = pod.volumes.iter().flatten().find(|v| {
            v.persistent_volume_claim
                .as_ref()
                .is_some_and(|p| p.claim_name == claim_name)
        });
        let vol = vol.unwrap_or_else(|| panic!("{j}: no volume of claim {claim_name}"));
        let mount = c
            .volume_mounts
            .iter()
            .flatten()
            .find(|m| m.name == vol.name)
            .unwrap_or_else(|| panic!("{j}: volume {} not mounted", vol.name));
        assert!(
            out.starts_with(&mount.mount_path),
            "{j}: {out} outside {}",
            mount.mount_path
        );
        let requests = c.resources.as_ref().and_then(|r| r.requests.clone());
        let requests = requests.unwrap_or_default();
        assert!(
            requests.contains_key("cpu") && requests.contains_key("memory"),
            "{j}"
        );
    }
}

#[test]
fn the_server_is_probed_on_its_health_port_with_secrets_for_tokens_and_tls() {
    let all = manifests();
    let objs: Vec<&Object> = all.iter().flat_map(|(_, o)| o).collect();
    let dep = objs
        .iter()
        .find_map(|o| match o {
            Object::Deployment(d) => Some(d.clone()),
            _ => None,
        })
        .expect("deployment");
    let c = container(&dep.spec.as_ref().expect("spec").template.spec);
    let health = env(&c, "FOVEAL_HEALTH_ADDR").expect("FOVEAL_HEALTH_ADDR");
    let health_port: i32 = health
        .rsplit_once(':')
        .and_then(|(_, p)| p.parse().ok())
        .expect("port");
    let addr = env(&c, "FOVEAL_ADDR").expect("FOVEAL_ADDR");
    assert!(
        addr.starts_with("0.0.0.0:"),
        "{addr}: reachable from the Service"
    );
    for (what, probe) in [
        ("startup", &c.startup_probe),
        ("liveness", &c.liveness_probe),
        ("readiness", &c.readiness_probe),
    ] {
        let grpc = probe
            .as_ref()
            .and_then(|p| p.grpc.clone())
            .unwrap_or_else(|| panic!("{what} probe is not gRPC"));
        assert_eq!(grpc.port, health_port, "{what} probe off the health port");
    }
    for var in [
        "FOVEAL_VIEWER_TOKEN",
        "FOVEAL_GAZE_TOKEN",
        "FOVEAL_ADMIN_TOKEN",
    ] {
        let e = c.env.iter().flatten().find(|e| e.name == var).expect(var);
        assert!(e.value.is_none(), "{var} written into the manifest");
        let from = e
            .value_from
            .as_ref()
            .and_then(|v| v.secret_key_ref.as_ref());
        assert!(from.is_some(), "{var} not from a Secret");
    }
    let pod = dep
        .spec
        .as_ref()
        .and_then(|s| s.template.spec.clone())
        .expect("pod");
    let tls = pod
        .volumes
        .iter()
        .flatten()
        .find(|v| v.secret.is_some())
        .expect("a TLS Secret volume");
    let mount = c
        .volume_mounts
        .iter()
        .flatten()
        .find(|m| m.name == tls.name)
        .expect("TLS mounted");
    for var in ["FOVEAL_TLS_CERT", "FOVEAL_TLS_KEY"] {
        let path = env(&c, var).expect(var);
        assert!(
            path.starts_with(&mount.mount_path),
            "{var}={path} outside the Secret"
        );
    }
    let requests = c.resources.as_ref().and_then(|r| r.requests.clone());
    let requests = requests.unwrap_or_default();
    assert!(requests.contains_key("cpu") && requests.contains_key("memory"));
    // The Service reaches the gRPC port by name.
    let svc = objs
        .iter()
        .find_map(|o| match o {
            Object::Service(s) => Some(s.clone()),
            _ => None,
        })
        .expect("service");
    let ports = svc
        .spec
        .as_ref()
        .and_then(|s| s.ports.clone())
        .unwrap_or_default();
    let names: Vec<String> = c
        .ports
        .iter()
        .flatten()
        .filter_map(|p| p.name.clone())
        .collect();
    for p in &ports {
        let target = p.target_port.as_ref().map(|t| match t {
            k8s_openapi::apimachinery::pkg::util::intstr::IntOrString::String(s) => s.clone(),
            k8s_openapi::apimachinery::pkg::util::intstr::IntOrString::Int(i) => i.to_string(),
        });
        assert!(
            target.is_some_and(|t| names.contains(&t)),
            "{p:?} targets no container port"
        );
    }
}

/// The flags after `<bench> study` in the Slurm script's command line, without the ones that
/// differ by scheduler (where to write, how many threads).
fn protocol_flags(args: &[String]) -> Vec<String> {
    let mut out = Vec::new();
    let mut it = args.iter().skip_while(|a| *a != "study").skip(1);
    while let Some(a) = it.next() {
        if a == "--out" || a == "--jobs" {
            it.next();
        } else {
            out.push(a.clone());
        }
    }
    out
}

#[test]
fn the_slurm_array_runs_the_kubernetes_jobs_protocol() {
    let text = std::fs::read_to_string(deploy_dir().join("slurm/study.sbatch")).expect("sbatch");
    assert!(text.contains("#SBATCH --array="), "not an array");
    assert!(!text.contains("--shard "), "the index comes from the array");
    let line = text
        .lines()
        .find(|l| l.trim_start().starts_with("exec ") && l.contains(" study "))
        .expect("the study's command line");
    let words: Vec<String> = line
        .split_whitespace()
        .map(|w| w.trim_matches('"').to_owned())
        .collect();
    let all = manifests();
    let shard = container(&job(&all, "foveal-study").spec.expect("spec").template.spec);
    let k8s = protocol_flags(&shard.args.unwrap_or_default());
    assert_eq!(protocol_flags(&words), k8s, "{line}");
    let merge = std::fs::read_to_string(deploy_dir().join("slurm/merge.sbatch")).expect("merge");
    assert!(merge.contains(" merge "), "merge.sbatch merges");
}
