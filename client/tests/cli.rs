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
async fn run(mut command: Command, stdin: &str) -> Output {
    let stdin = stdin.to_owned();
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

/// A file in the temporary directory, unique to this test process.
fn scratch(name: &str) -> std::path::PathBuf {
    std::env::temp_dir().join(format!("foveal-cli-{}-{name}", std::process::id()))
}

/// The EyeLink recording made binocular (the right eye a copy of the left), and its reference
/// list with each fixation listed for both eyes, as a binocular tracker's parser lists them.
fn binocular_recording() -> (std::path::PathBuf, std::path::PathBuf) {
    let mono = std::fs::read_to_string(gaze_data("eyelink-1000hz-left.samples.csv"))
        .expect("the recording");
    let mut csv =
        String::from("# screen 1920x1080 px\nt_s,xpos_left,xpos_right,ypos_left,ypos_right\n");
    for line in mono.lines().filter(|l| !l.starts_with('#')).skip(1) {
        let f: Vec<&str> = line.split(',').collect();
        csv.push_str(&format!("{},{},{},{},{}\n", f[0], f[1], f[1], f[2], f[2]));
    }
    let fixations = std::fs::read_to_string(gaze_data("eyelink-1000hz-left.fixations.csv"))
        .expect("the reference");
    let mut reference = String::from("eye,start_s,end_s,x_px,y_px\n");
    for eye in ["0", "1"] {
        for line in fixations.lines().filter(|l| l.starts_with("0,")) {
            reference.push_str(&format!("{eye}{}\n", &line[1..]));
        }
    }
    let (samples, listed) = (scratch("binocular.csv"), scratch("binocular.fixations.csv"));
    std::fs::write(&samples, csv).expect("write");
    std::fs::write(&listed, reference).expect("write");
    (samples, listed)
}

/// The number after `key` on the first line of `text` that has it.
fn number_after(text: &str, key: &str) -> f64 {
    text.lines()
        .find_map(|l| {
            l.split(key)
                .nth(1)?
                .split(|c: char| c == ',' || c.is_whitespace())
                .next()?
                .parse()
                .ok()
        })
        .unwrap_or_else(|| panic!("no {key:?} in {text}"))
}

#[test]
fn compare_scores_each_eye_against_its_own_reference() {
    let (samples, reference) = binocular_recording();
    let compare = |eyes: &str| {
        foveal()
            .arg("fixations")
            .arg(&samples)
            .args(["--eyes", eyes, "--compare"])
            .arg(&reference)
            .output()
            .expect("foveal runs")
    };
    // One eye: its 21 reference fixations, not the 42 of both eyes.
    let out = compare("left");
    assert!(out.status.success(), "{}", text(&out.stderr));
    let stdout = text(&out.stdout);
    assert_eq!(number_after(&stdout, "reference "), 21.0, "{stdout}");
    assert!(number_after(&stdout, "F1 ") >= 0.9, "{stdout}");
    // Both eyes: each scored apart, then pooled.
    let out = compare("both");
    assert!(out.status.success(), "{}", text(&out.stderr));
    let stdout = text(&out.stdout);
    for eye in ["# left eye:", "# right eye:"] {
        let line = stdout
            .lines()
            .find(|l| l.starts_with(eye))
            .unwrap_or_else(|| panic!("no {eye} line: {stdout}"));
        assert_eq!(number_after(line, "reference "), 21.0, "{line}");
        assert!(number_after(line, "F1 ") >= 0.9, "{line}");
    }
    // The mean of the eyes cannot be scored against a list of each eye apart.
    let out = compare("mean");
    assert_eq!(out.status.code(), Some(1));
    assert!(
        text(&out.stderr).contains("lists each eye apart"),
        "{}",
        text(&out.stderr)
    );
    let _ = std::fs::remove_file(samples);
    let _ = std::fs::remove_file(reference);
}

#[test]
fn fixations_says_when_it_drops_backwards_timestamps() {
    let path = scratch("backwards.csv");
    let mut csv = String::from("t_s,x,y\n");
    for i in 0..100 {
        csv.push_str(&format!("{},0.5,0.5\n", f64::from(i) * 0.01));
        if i == 49 {
            // Three samples stamped before the one just written.
            for t in ["0.40", "0.41", "0.42"] {
                csv.push_str(&format!("{t},0.5,0.5\n"));
            }
        }
    }
    std::fs::write(&path, csv).expect("write");
    let out = foveal()
        .arg("fixations")
        .arg(&path)
        .output()
        .expect("foveal runs");
    let stderr = text(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(
        stderr.contains(
            "dropped: 3 sample(s) of eye 2 from t = 0.4000 s go back before t = 0.4900 s"
        ),
        "{stderr}"
    );
    let _ = std::fs::remove_file(path);
}

/// `n` samples at `rate_hz` of a fixed point, normalised CSV, in a scratch file.
fn fixed_csv(name: &str, n: u32, rate_hz: f64) -> std::path::PathBuf {
    let mut csv = String::from("t_s,x,y\n");
    for i in 0..n {
        csv.push_str(&format!("{:.6},0.5,0.5\n", f64::from(i) / rate_hz));
    }
    let path = scratch(name);
    std::fs::write(&path, csv).expect("write");
    path
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_csv_file_is_paced_at_its_own_rate_and_unpaced_sending_is_warned_about() {
    // A server with a low gaze rate limit: 200 samples/s after a burst of 50.
    let mut config = foveal_tests::small_config(40, 30.0);
    config.limits.max_gaze_rate_hz = 200.0;
    let server = foveal_tests::TestServer::start(config).await;
    drop(server.channel().await);
    let addr = server.url();

    // 1.5 s at 100 Hz: paced by default, every sample is within the limit.
    let paced = fixed_csv("paced.csv", 150, 100.0);
    let mut bridge = foveal();
    bridge.args(["bridge", "--addr", &addr, "csv"]).arg(&paced);
    let out = run(bridge, "").await;
    let stdout = text(&out.stdout);
    assert!(out.status.success(), "{}", text(&out.stderr));
    assert!(
        stdout.contains("sent 150, accepted 150, rejected 0"),
        "{stdout}"
    );
    assert!(!stdout.contains("rate-limited"), "{stdout}");

    // Unpaced, the bridge says before sending what the rate limit will do.
    let long = fixed_csv("unpaced.csv", 1200, 1000.0);
    let mut bridge = foveal();
    bridge
        .args(["bridge", "--addr", &addr, "csv", "--as-fast-as-possible"])
        .arg(&long);
    let out = run(bridge, "").await;
    let (stdout, stderr) = (text(&out.stdout), text(&out.stderr));
    assert!(out.status.success(), "{stderr}");
    assert!(
        stderr.contains("sending without pacing")
            && stderr.contains("1200 samples at 1000 Hz will mostly be dropped"),
        "{stderr}"
    );
    // A log read from a pipe or a file carries no colour codes.
    assert!(
        !stderr.contains('\u{1b}'),
        "colour codes off a terminal: {stderr:?}"
    );
    assert!(stdout.contains("rate-limited"), "{stdout}");
    server.stop().await.expect("clean stop");
    let _ = std::fs::remove_file(paced);
    let _ = std::fs::remove_file(long);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_file_that_sends_nothing_is_one_clear_error() {
    let server = TestServer::start().await;
    let mut pixels = String::from("t_s,xpos,ypos\n");
    for i in 0..2000 {
        pixels.push_str(&format!("{},960,540\n", f64::from(i) * 0.001));
    }
    let asc_without_screen = "SAMPLES\tGAZE\tLEFT\tRATE\t1000.00\n1000\t960.0\t540.0\t1103.0\n";
    for (name, content, command, why) in [
        ("empty.csv", "", "csv", "it has no data line"),
        (
            "header.csv",
            "# screen 1920x1080 px\nt_s,xpos,ypos\n",
            "csv",
            "it has no data line",
        ),
        (
            "noscreen.csv",
            pixels.as_str(),
            "csv",
            "all 2000 of its data lines were skipped",
        ),
        (
            "noscreen.asc",
            asc_without_screen,
            "asc",
            "the screen size is unknown",
        ),
    ] {
        let path = scratch(name);
        std::fs::write(&path, content).expect("write");
        let mut bridge = foveal();
        bridge
            .args(["bridge", "--addr", &server.addr, command])
            .arg(&path);
        let out = run(bridge, "").await;
        let stderr = text(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{name}: {stderr}");
        let errors: Vec<&str> = stderr.lines().filter(|l| l.starts_with("error:")).collect();
        assert_eq!(errors.len(), 1, "{name}: {stderr}");
        assert!(errors[0].contains(why), "{name}: {stderr}");
        assert!(
            stderr.lines().count() <= 2,
            "{name}: one error, no flood of warnings: {stderr}"
        );
        let _ = std::fs::remove_file(path);
    }

    // From stdin too: the repeated fault is logged once, counted, and the exit code says so.
    let mut stdin = String::from("t_s,xpos,ypos\n");
    for i in 0..50 {
        stdin.push_str(&format!("{},960,540\n", f64::from(i) * 0.001));
    }
    let mut bridge = foveal();
    bridge.args(["bridge", "--addr", &server.addr, "csv", "-"]);
    let out = run(bridge, &stdin).await;
    let (stdout, stderr) = (text(&out.stdout), text(&out.stderr));
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert_eq!(
        stderr.matches("skipping malformed input").count(),
        1,
        "{stderr}"
    );
    assert!(stderr.contains("skipped 50 lines like line 2"), "{stderr}");
    assert!(
        stderr.contains("error: bridge:csv:stdin: the input ended without a gaze sample"),
        "{stderr}"
    );
    assert!(
        stdout.contains("50 skipped like line 2: field `xpos`"),
        "{stdout}"
    );
    server.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_bridge_summary_counts_every_rejection_by_reason() {
    let server = TestServer::start().await;
    // 40 blinks, two samples stamped back in time, one good sample: 42 rejections, more than
    // the server lists one by one.
    let mut input = String::from("t_s,x,y,validity\n");
    for i in 0..40 {
        input.push_str(&format!("{:.2},,,0\n", f64::from(i) * 0.01));
    }
    input.push_str("0.10,0.5,0.5,1\n0.11,0.5,0.5,1\n0.50,0.5,0.5,1\n");
    let mut bridge = foveal();
    bridge.args(["bridge", "--addr", &server.addr, "csv", "-"]);
    let out = run(bridge, &input).await;
    let stdout = text(&out.stdout);
    assert!(out.status.success(), "{}", text(&out.stderr));
    assert!(
        stdout.contains("accepted 1, rejected 42 (time_backwards 2, missing 40)"),
        "{stdout}"
    );
    server.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_file_bridges_send_the_eye_asked_for() {
    let server = TestServer::start().await;
    // The left eye looks at x = 0.2, the right at x = 0.8: their mean would be 0.5.
    let mut csv = String::from("t_s,x_left,y_left,x_right,y_right\n");
    for i in 0..50 {
        csv.push_str(&format!("{:.3},0.2,0.5,0.8,0.5\n", f64::from(i) * 0.002));
    }
    let path = scratch("eyes.csv");
    std::fs::write(&path, csv).expect("write");
    let mut bridge = foveal();
    bridge
        .args(["bridge", "--addr", &server.addr, "csv", "--eyes", "left"])
        .arg(&path);
    let out = run(bridge, "").await;
    assert!(out.status.success(), "{}", text(&out.stderr));
    assert!(
        text(&out.stdout).contains("accepted 50"),
        "{}",
        text(&out.stdout)
    );
    let mut client = foveal_client::connect(&server.addr).await.expect("connect");
    let mut frames = client
        .watch_frames(foveal_proto::pb::WatchFramesRequest {
            every_k: 1,
            ..Default::default()
        })
        .await
        .expect("watch")
        .into_inner();
    let fixation = tokio::time::timeout(std::time::Duration::from_secs(20), async {
        loop {
            let frame = frames.message().await.expect("frames").expect("a frame");
            let f = frame.fixation.expect("a fixation");
            if f.source == foveal_proto::pb::FixationSource::Gaze as i32 {
                return f;
            }
        }
    })
    .await
    .expect("a frame steered by the gaze");
    assert!(
        (fixation.x - 0.2).abs() < 1e-9,
        "the left eye steers: {fixation:?}"
    );
    let _ = std::fs::remove_file(path);
    server.stop().await;
}

/// The bridges warn about a server's default gaze rate limit before sending: the figure they
/// quote is the server's.
#[test]
fn the_rate_limit_the_bridges_quote_is_the_servers_default() {
    let limits = foveal_server::Limits::default();
    assert_eq!(
        foveal_client::bridge::SERVER_DEFAULT_GAZE_RATE_HZ,
        limits.max_gaze_rate_hz
    );
    assert_eq!(
        foveal_client::bridge::SERVER_DEFAULT_GAZE_BURST,
        limits.max_gaze_rate_hz / 4.0
    );
}
