//! The `foveal` binary against an in-process server: argument parsing, stdout results, exit codes.

mod common;

use std::io::Write;
use std::process::{Command, Output, Stdio};

use common::{TestServer, gaze_data};

fn foveal() -> Command {
    let mut command = Command::new(env!("CARGO_BIN_EXE_foveal"));
    command.env("RUST_LOG", "warn");
    command
}

/// Runs `command` off the async workers (the server shares the runtime) with `stdin` piped in.
async fn run(mut command: Command, stdin: &'static str) -> Output {
    tokio::task::spawn_blocking(move || {
        let mut child = command
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .expect("spawn foveal");
        if let Some(mut input) = child.stdin.take() {
            input.write_all(stdin.as_bytes()).expect("write stdin");
        }
        child.wait_with_output().expect("foveal runs")
    })
    .await
    .expect("join")
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn commands_talk_to_the_server_and_exit_with_the_right_code() {
    let server = TestServer::start().await;
    let addr_owned = server.addr.clone();
    let addr = addr_owned.as_str();

    let mut health = foveal();
    health.args(["health", "--addr", addr]);
    let out = run(health, "").await;
    assert!(out.status.success(), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout).trim(), "SERVING");

    // 0.25 s of a fixed point at 40 Hz in batches of 4: 10 samples, real time.
    let mut gaze = foveal();
    gaze.args([
        "gaze",
        "--addr",
        addr,
        "--transport",
        "push",
        "--batch",
        "4",
    ])
    .args(["--rate", "40", "--duration", "0.25", "fixed", "--x", "0.3"]);
    let out = run(gaze, "").await;
    let stdout = text(&out.stdout);
    assert!(out.status.success(), "{}", text(&out.stderr));
    assert!(
        stdout.contains("sent 10, accepted 10, rejected 0"),
        "{stdout}"
    );

    let mut replay = foveal();
    replay
        .args([
            "gaze",
            "replay",
            "--as-fast-as-possible",
            "--duration",
            "0.5",
        ])
        .arg(gaze_data("eyelink-1000hz-left.asc"))
        .args(["--addr", addr]);
    let out = run(replay, "").await;
    let stdout = text(&out.stdout);
    assert!(out.status.success(), "{}", text(&out.stderr));
    assert!(stdout.contains("accepted 500, rejected 0"), "{stdout}");

    // Live CSV from stdin, with one malformed line and one blink.
    let mut bridge = foveal();
    bridge.args(["bridge", "--addr", addr, "csv", "-"]);
    let input = "t_s,x,y,validity\n0.0,0.5,0.5,1\n0.1,oops,0.5,1\n0.2,,,0\n0.3,0.6,0.4,1\n";
    let out = run(bridge, input).await;
    let stdout = text(&out.stdout);
    let stderr = text(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(
        stdout.contains("3 samples (2 valid, 1 invalid), 1 malformed lines skipped"),
        "{stdout}"
    );
    assert!(stdout.contains("accepted 2, rejected 1"), "{stdout}");
    assert!(
        stderr.contains("line 3"),
        "the malformed line is logged: {stderr}"
    );

    let mut watch = foveal();
    watch.args(["watch", "--addr", addr, "--frames", "3", "--csv", "-"]);
    let out = run(watch, "").await;
    let stdout = text(&out.stdout);
    assert!(out.status.success(), "{}", text(&out.stderr));
    assert_eq!(stdout.lines().count(), 4, "header and 3 rows: {stdout}");
    assert!(stdout.starts_with("index,sim_time_s,"), "{stdout}");

    server.stop().await;

    let mut health = foveal();
    health.args(["health", "--addr", addr, "--timeout-ms", "300"]);
    let out = run(health, "").await;
    assert_eq!(out.status.code(), Some(1), "no server: unhealthy");
}

/// `foveal fixations` on the EyeLink recording in `data/gaze`, scored against the tracker's own parser:
/// the documented target (F1 >= 0.9, median onset and offset differences <= 10 ms), read from
/// the command's own output; the output reads back as a fixation list.
#[test]
fn fixations_agree_with_the_tracker_parser_on_the_eyelink_recording() {
    let recording = gaze_data("eyelink-1000hz-left.asc");
    let reference = gaze_data("eyelink-1000hz-left.fixations.csv");
    let out = foveal()
        .arg("fixations")
        .arg(&recording)
        .arg("--compare")
        .arg(&reference)
        .output()
        .expect("foveal runs");
    assert!(out.status.success(), "{}", text(&out.stderr));
    let stdout = text(&out.stdout);
    let listed =
        foveal_client::gaze::fixation_list::read(stdout.as_bytes()).expect("a fixation list");
    assert_eq!(listed.len(), 19, "{stdout}");
    assert!(listed.iter().all(|f| f.eye == 0), "the ASC file says LEFT");
    let f1: f64 = stdout
        .lines()
        .find_map(|l| {
            l.strip_prefix("# precision ")?
                .split("F1 ")
                .nth(1)?
                .trim()
                .parse()
                .ok()
        })
        .expect("an F1 line");
    assert!(f1 >= 0.9, "{stdout}");
    let median = |kind: &str| -> f64 {
        stdout
            .lines()
            .find_map(|l| {
                let rest = l.strip_prefix(&format!("# {kind} difference"))?;
                rest.split("median |d| ")
                    .nth(1)?
                    .split(" ms")
                    .next()?
                    .parse()
                    .ok()
            })
            .expect("a timing line")
    };
    assert!(
        median("onset") <= 10.0 && median("offset") <= 10.0,
        "{stdout}"
    );

    // A bad option is refused with the field named, before any work.
    let out = foveal()
        .args(["fixations", "--distance-cm", "0"])
        .arg(&recording)
        .output()
        .expect("foveal runs");
    assert!(!out.status.success());
    assert!(
        text(&out.stderr).contains("distance_cm"),
        "{}",
        text(&out.stderr)
    );
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn pupil_and_lsl_bridges_refuse_bad_flags_and_name_a_missing_peer() {
    for (args, expected) in [
        (
            &["bridge", "pupil", "--min-confidence", "1.5"][..],
            "--min-confidence must be in 0..=1",
        ),
        (
            &["bridge", "pupil", "--connect-timeout", "0"][..],
            "--connect-timeout must be a number of seconds",
        ),
        (
            &["bridge", "lsl", "--units", "pixels"][..],
            "--units pixels needs --screen",
        ),
        (
            &["bridge", "lsl", "--screen", "1920x1080"][..],
            "--screen is for --units pixels",
        ),
    ] {
        let mut command = foveal();
        command.args(args);
        let out = run(command, "").await;
        assert_eq!(out.status.code(), Some(1), "{args:?}");
        assert!(
            text(&out.stderr).contains(expected),
            "{args:?}: {}",
            text(&out.stderr)
        );
    }

    // Nobody listens on the port: the bridge gives up within its timeout, names the address,
    // and exits 1.
    let server = TestServer::start().await;
    let port = std::net::TcpListener::bind("127.0.0.1:0")
        .and_then(|l| l.local_addr())
        .expect("a free port")
        .port()
        .to_string();
    let mut command = foveal();
    command.args([
        "bridge",
        "--addr",
        &server.addr,
        "pupil",
        "--port",
        &port,
        "--connect-timeout",
        "0.5",
    ]);
    let started = std::time::Instant::now();
    let out = run(command, "").await;
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stderr));
    assert!(started.elapsed() < std::time::Duration::from_secs(10));
    let stdout = text(&out.stdout);
    assert!(
        stdout.contains(&format!("source failed: Pupil Remote at 127.0.0.1:{port}")),
        "{stdout}"
    );
    server.stop().await;
}
