//! The `foveal-server` binary as an operator runs it: its log (plain text when not on a
//! terminal; refused credentials at info, rate-limited, never the token), its start-up errors
//! (a tokens-file line written backwards does not echo the token), and its accept loop at the
//! descriptor limit (backs off and says so instead of spinning, and serves again once
//! descriptors are free).

use std::io::{BufRead, BufReader};
use std::net::SocketAddr;
use std::process::{Child, Command, Stdio};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use foveal_proto::pb;
use foveal_proto::pb::foveal_client::FovealClient;

const BIN: &str = env!("CARGO_BIN_EXE_foveal-server");
/// Generous bound on anything that should take a moment.
const PATIENCE: Duration = Duration::from_secs(20);
const ADMIN: &str = "admin-token-for-the-binary-test";
const WRONG: &str = "guessed-token-0123456789-abcdef";

/// A server process and everything it has written to stderr so far.
struct Server {
    child: Child,
    log: Arc<Mutex<String>>,
}

impl Server {
    /// Start `command` (stderr piped, as in a container or under a service manager).
    fn spawn(mut command: Command) -> Self {
        let mut child = command
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .expect("start foveal-server");
        let stderr = child.stderr.take().expect("piped stderr");
        let log = Arc::new(Mutex::new(String::new()));
        let sink = Arc::clone(&log);
        std::thread::spawn(move || {
            for line in BufReader::new(stderr).lines() {
                let Ok(line) = line else { break };
                let mut log = sink.lock().expect("log lock");
                log.push_str(&line);
                log.push('\n');
            }
        });
        Self { child, log }
    }

    fn log(&self) -> String {
        self.log.lock().expect("log lock").clone()
    }

    /// Wait for a log line containing `what`; the whole log so far.
    fn wait_for(&mut self, what: &str) -> String {
        let until = Instant::now() + PATIENCE;
        loop {
            let log = self.log();
            if log.contains(what) {
                return log;
            }
            if let Ok(Some(status)) = self.child.try_wait() {
                panic!("foveal-server exited ({status}) before logging `{what}`:\n{log}");
            }
            assert!(
                Instant::now() < until,
                "no `{what}` in the log within {PATIENCE:?}:\n{log}"
            );
            std::thread::sleep(Duration::from_millis(20));
        }
    }

    /// The address from the `serving` line.
    fn addr(&mut self) -> SocketAddr {
        let log = self.wait_for("serving");
        let at = log
            .find("addr=")
            .expect("the serving line names the address")
            + 5;
        let end = log[at..]
            .find(char::is_whitespace)
            .map_or(log.len(), |e| at + e);
        log[at..end].parse().expect("a socket address")
    }

    /// CPU time (user + system) the process has used.
    fn cpu(&self) -> Duration {
        let stat = std::fs::read_to_string(format!("/proc/{}/stat", self.child.id()))
            .expect("/proc/PID/stat");
        // Fields after the parenthesised command name; utime and stime are the 14th and 15th.
        let rest = &stat[stat.rfind(')').expect("comm") + 2..];
        let f: Vec<u64> = rest
            .split_whitespace()
            .skip(11)
            .take(2)
            .map(|v| v.parse().expect("ticks"))
            .collect();
        let hz = rustix::param::clock_ticks_per_second();
        Duration::from_secs_f64((f[0] + f[1]) as f64 / hz as f64)
    }

    fn stop(mut self) -> String {
        let pid = rustix::process::Pid::from_raw(i32::try_from(self.child.id()).expect("pid"))
            .expect("a pid");
        let _ = rustix::process::kill_process(pid, rustix::process::Signal::TERM);
        let until = Instant::now() + PATIENCE;
        while self.child.try_wait().expect("wait").is_none() {
            if Instant::now() > until {
                let _ = self.child.kill();
                break;
            }
            std::thread::sleep(Duration::from_millis(20));
        }
        // The reader thread ends with the pipe; give it a moment to take the last lines.
        std::thread::sleep(Duration::from_millis(50));
        self.log()
    }
}

impl Drop for Server {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

fn small(args: &[&str]) -> Command {
    let mut c = Command::new(BIN);
    c.args([
        "--addr",
        "127.0.0.1:0",
        "-n",
        "50",
        "--threads",
        "1",
        "--frame-rate",
        "10",
    ])
    .args(args)
    .env_remove("NO_COLOR")
    .env_remove("FOVEAL_LOG");
    c
}

async fn try_client(
    addr: SocketAddr,
) -> Result<FovealClient<tonic::transport::Channel>, tonic::transport::Error> {
    let channel = tonic::transport::Endpoint::from_shared(format!("http://{addr}"))
        .expect("url")
        .connect_timeout(Duration::from_secs(2))
        .connect()
        .await?;
    Ok(FovealClient::new(channel))
}

async fn client(addr: SocketAddr) -> FovealClient<tonic::transport::Channel> {
    try_client(addr).await.expect("connect")
}

#[tokio::test]
async fn logs_are_plain_and_refused_credentials_are_logged_once_without_the_token() {
    let mut cmd = small(&[]);
    cmd.env("FOVEAL_ADMIN_TOKEN", ADMIN);
    let mut server = Server::spawn(cmd);
    let addr = server.addr();
    let mut c = client(addr).await;
    for _ in 0..5 {
        let mut req = tonic::Request::new(pb::GetStatusRequest {});
        req.metadata_mut().insert(
            "authorization",
            format!("Bearer {WRONG}").parse().expect("header"),
        );
        let e = c.get_status(req).await.expect_err("an unknown token");
        assert_eq!(e.code(), tonic::Code::Unauthenticated);
        assert!(!e.message().contains(WRONG), "{}", e.message());
    }
    let log = server.wait_for("call refused");
    let log = {
        // Let any further line (there must be none) arrive.
        tokio::time::sleep(Duration::from_millis(200)).await;
        let _ = log;
        server.stop()
    };
    assert!(
        !log.contains('\u{1b}'),
        "colour codes in a piped log:\n{log}"
    );
    let refused: Vec<_> = log.lines().filter(|l| l.contains("call refused")).collect();
    assert_eq!(refused.len(), 1, "one line per period:\n{log}");
    assert!(refused[0].contains("INFO"), "{}", refused[0]);
    assert!(refused[0].contains("GetStatus"), "{}", refused[0]);
    assert!(
        !log.contains(WRONG),
        "the presented token is never logged:\n{log}"
    );
    assert!(
        !log.contains(ADMIN),
        "a configured token is never logged:\n{log}"
    );
}

#[test]
fn a_tokens_file_line_written_backwards_does_not_echo_the_token() {
    let dir = std::env::temp_dir().join(format!("foveal-binary-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let file = dir.join("tokens");
    let secret = "f00dfeedc0ffee-0123456789abcdef";
    std::fs::write(&file, format!("viewer {ADMIN}x\n{secret} admin\n")).expect("tokens file");
    let out = Command::new(BIN)
        .args(["--addr", "127.0.0.1:0", "-n", "50", "--tokens"])
        .arg(&file)
        .output()
        .expect("run foveal-server");
    let _ = std::fs::remove_dir_all(&dir);
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("line 2"), "{err}");
    assert!(!err.contains("f00dfeed"), "the token is echoed:\n{err}");
    assert!(!err.contains(ADMIN), "{err}");
}

#[tokio::test]
async fn at_the_descriptor_limit_the_accept_loop_backs_off_and_recovers() {
    // 48 descriptors, and a connection limit above them on purpose: accept then fails with
    // EMFILE. Connections are closed by the first-byte timeout, so that descriptors come back.
    let mut cmd = Command::new("sh");
    cmd.arg("-c")
        .arg("ulimit -n 48 && exec \"$0\" \"$@\"")
        .arg(BIN)
        .args([
            "--addr",
            "127.0.0.1:0",
            "-n",
            "50",
            "--threads",
            "1",
            "--frame-rate",
            "10",
            "--max-connections",
            "1000",
            "--first-byte-timeout",
            "3",
        ]);
    let mut server = Server::spawn(cmd);
    let addr = server.addr();
    let mut idle = Vec::new();
    for _ in 0..80 {
        idle.push(tokio::net::TcpStream::connect(addr).await.expect("connect"));
    }
    let log = server.wait_for("cannot accept connections");
    assert!(log.contains("ulimit -n"), "{log}");
    // While the descriptors stay exhausted, the process must not spin.
    let cpu0 = server.cpu();
    let t0 = Instant::now();
    tokio::time::sleep(Duration::from_millis(1000)).await;
    let used = server.cpu() - cpu0;
    let wall = t0.elapsed();
    println!("at EMFILE: {used:?} of CPU in {wall:?}");
    assert!(
        used < wall / 3,
        "{used:?} of CPU in {wall:?} at the descriptor limit"
    );
    // The idle clients go; a fresh client is served.
    drop(idle);
    let served = tokio::time::timeout(PATIENCE, async {
        loop {
            if let Ok(Ok(mut c)) =
                tokio::time::timeout(Duration::from_secs(2), try_client(addr)).await
                && c.get_status(pb::GetStatusRequest {}).await.is_ok()
            {
                return;
            }
            tokio::time::sleep(Duration::from_millis(50)).await;
        }
    })
    .await;
    let log = server.stop();
    assert!(
        served.is_ok(),
        "no client served after the idle ones left:\n{log}"
    );
    let lines = log
        .lines()
        .filter(|l| l.contains("cannot accept connections"))
        .count();
    assert!(lines <= 2, "the warning is rate-limited:\n{log}");
}
