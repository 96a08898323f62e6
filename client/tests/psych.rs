//! `foveal psych`: simulated viewers written as a results CSV, fitted, and the fitted model
//! string accepted by the server's `--schedule-model`.

use std::process::Command;
use std::str::FromStr;

use foveal_server::cli::ModelArg;

fn foveal(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_foveal"))
        .args(args)
        .env("RUST_LOG", "warn")
        .output()
        .expect("foveal runs")
}

#[test]
fn simulated_viewers_are_fitted_and_the_model_string_schedules() {
    let dir = std::env::temp_dir().join(format!("foveal-psych-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let trials = dir.join("trials.csv");
    let out = foveal(&[
        "psych",
        "simulate",
        "--c",
        "6",
        "--observers",
        "2",
        "--repetitions",
        "30",
        "--replicates",
        "30",
        "--trials-out",
        trials.to_str().expect("utf-8 path"),
    ]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        stdout.contains("2 simulated viewers, 1200 trials each, true C = 6 deg"),
        "{stdout}"
    );
    let fitted = dir.join("fit");
    let out = foveal(&[
        "psych",
        "fit",
        trials.to_str().expect("utf-8 path"),
        "--replicates",
        "40",
        "--out",
        fitted.to_str().expect("utf-8 path"),
    ]);
    let report = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{report}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // Pooled and both participants, each with the three functions.
    for group in [
        "## pooled (2400 trials)",
        "## sim1000 (1200 trials)",
        "## sim1001",
    ] {
        assert!(report.contains(group), "{group} missing:\n{report}");
    }
    assert_eq!(report.matches("| F3 |").count(), 3, "{report}");
    let model = std::fs::read_to_string(fitted.join("model.txt")).expect("model.txt");
    let ModelArg(parsed) = ModelArg::from_str(model.trim()).expect("the server takes it");
    let c = match parsed.function {
        foveal_engine::PerceptualFunction::F2 { c } => c,
        other => panic!("not F2: {other:?}"),
    };
    assert!(
        (c - 6.0).abs() < 1.5,
        "fitted C {c} from 2,400 trials of C = 6"
    );
    let svg = std::fs::read_to_string(fitted.join("fit.svg")).expect("fit.svg");
    assert!(svg.starts_with("<svg") && svg.contains("<circle"));

    // One condition apart (`--where`): here one participant's rows; a value no row holds, a
    // column the file lacks and a malformed selection are refused by name.
    let path = trials.to_str().expect("utf-8 path");
    let fit_where = |selection: &str| {
        foveal(&[
            "psych",
            "fit",
            path,
            "--replicates",
            "20",
            "--pooled-only",
            "--where",
            selection,
        ])
    };
    let out = fit_where("participant=sim1001");
    let report = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{report}");
    assert!(
        report.starts_with("Trials fitted: those with participant = sim1001 (1200 trials).")
            && report.contains("## pooled (1200 trials)"),
        "{report}"
    );
    let out = fit_where("participant=nobody");
    assert_eq!(out.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("no valid trial has participant = nobody"),
        "{stderr}"
    );
    let out = fit_where("distractors=8");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("no `distractors` column"), "{stderr}");
    let out = fit_where("distractors");
    assert!(!out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("is not COLUMN=VALUE"), "{stderr}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_malformed_results_file_is_refused_naming_the_line() {
    let dir = std::env::temp_dir().join(format!("foveal-psych-bad-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let file = dir.join("bad.csv");
    std::fs::write(
        &file,
        "participant,eccentricity_deg,gap_deg,response\np1,2.5,0.1,apart\np1,2.5,0.1,maybe\n",
    )
    .expect("write");
    let out = foveal(&["psych", "fit", file.to_str().expect("utf-8 path")]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        stderr.contains("bad.csv line 3: `response` = `maybe`: expected `apart` or `touching`"),
        "{stderr}"
    );
    std::fs::remove_dir_all(&dir).ok();
}
