//! A tiny study through the library API: every mode, scheduler and output of the protocol of the
//! paper's section 4 (and the budget sweep), with a handful of frames, so `cargo test` covers the
//! whole pipeline in seconds.

use std::path::{Path, PathBuf};

use foveal_bench::open_loop::{Budget, OpenLoopConfig};
use foveal_bench::protocol::{CurvesConfig, StudyConfig};
use foveal_bench::{GazeSpec, run_study};
use foveal_engine::SchedulerKind;

fn out_dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("foveal-bench-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

fn tiny(out: PathBuf) -> StudyConfig {
    StudyConfig {
        ns: vec![10, 30],
        frames: 6,
        seeds: vec![1, 2],
        fractions: vec![0.1],
        // The second covers every exact frame: a cell that never interrupts.
        tests_budgets: vec![200, 1_000_000],
        curves: Some(CurvesConfig {
            ns: vec![30],
            frames: 4,
            fractions: vec![0.05, 0.5],
        }),
        open_loop: Some(tiny_open_loop()),
        grid: Some(tiny_grid()),
        calibration_frames: 3,
        warmup_frames: 2,
        jobs: 2,
        progress: false,
        out,
        ..StudyConfig::default()
    }
}

/// The open-loop part at N = 150, two seeds of a few frames, two sphere-test budgets.
fn tiny_open_loop() -> OpenLoopConfig {
    let mut ol = OpenLoopConfig::quick();
    ol.ns = vec![150];
    ol.seeds = vec![1, 2];
    ol.frames = vec![(150, 4)];
    ol.warmup = 5;
    ol.timing_frames = 2;
    ol.budgets = vec![Budget::Tests(0.05), Budget::Tests(0.3)];
    ol.conditions.truncate(1);
    ol
}

/// The sensitivity grid at two models and one budget (its frames are the open-loop part's).
fn tiny_grid() -> OpenLoopConfig {
    let mut g = OpenLoopConfig::grid();
    g.ns = vec![150];
    g.budgets = vec![Budget::Tests(0.3)];
    g.conditions.truncate(2);
    g
}

/// Parse a CSV: a header and rows of the same width whose non-empty fields are numbers, except
/// the named text columns and the stamp's (`commit`, `engine_hash`: every row says what computed
/// it, this build's engine).
fn parse_csv(path: &Path, text_cols: &[&str]) -> (Vec<String>, Vec<Vec<String>>) {
    let text = std::fs::read_to_string(path).expect("csv readable");
    let mut lines = text.lines();
    let header: Vec<String> = lines
        .next()
        .expect("header")
        .split(',')
        .map(String::from)
        .collect();
    let rows: Vec<Vec<String>> = lines
        .map(|l| l.split(',').map(String::from).collect())
        .collect();
    assert!(!rows.is_empty(), "{} has no rows", path.display());
    for r in &rows {
        assert_eq!(r.len(), header.len(), "{}: {r:?}", path.display());
        for (h, v) in header.iter().zip(r) {
            if h == "engine_hash" {
                assert_eq!(
                    v,
                    foveal_bench::stamp::current().engine,
                    "{}",
                    path.display()
                );
            }
            if text_cols.contains(&h.as_str())
                || ["commit", "engine_hash", "primary"].contains(&h.as_str())
                || v.is_empty()
            {
                continue;
            }
            assert!(
                v.parse::<f64>().is_ok(),
                "{}: column {h} = {v:?} is not a number",
                path.display()
            );
        }
    }
    (header, rows)
}

#[test]
fn tiny_study_writes_every_output_and_the_csvs_parse() {
    let out = out_dir("tiny");
    let cfg = tiny(out.clone());
    let res = run_study(&cfg).expect("study runs");
    // 2 N x 2 seeds x (exact + zero + 7 schedulers x (fraction + ms + 2 tests)) + curves 2 x 2 x 7
    // + the F1 case, 2 N x 2 seeds x (zero + 2 schedulers at the fraction and the target time).
    let k = SchedulerKind::ALL.len();
    assert_eq!(k, 7);
    assert_eq!(res.runs.len(), 2 * 2 * (2 + k * 4) + 2 * 2 * k + 2 * 2 * 5);
    for f in [
        "table_runs.csv",
        "table_summary.csv",
        "table_report.md",
        "curves_runs.csv",
        "curves_summary.csv",
        "curves_report.md",
        "f1_runs.csv",
        "f1_summary.csv",
        "f1_report.md",
    ] {
        assert!(out.join(f).is_file(), "missing {f}");
    }
    for fig in [
        "fig4_time",
        "fig5_inaccuracy",
        "fig6_schedulers_f0.1",
        "fig6_schedulers_ms",
        "curves_n30",
        "fig5b_6a_f1_sorted",
    ] {
        for ext in ["svg", "png"] {
            let p = out.join("figures").join(format!("{fig}.{ext}"));
            let len = std::fs::metadata(&p).map(|m| m.len()).unwrap_or(0);
            assert!(len > 100, "missing or empty {}", p.display());
        }
    }
    let (_, runs) = parse_csv(&out.join("table_runs.csv"), &["part", "mode", "scheduler"]);
    assert_eq!(runs.len(), 2 * 2 * (2 + k * 4));
    let (h, summary) = parse_csv(
        &out.join("table_summary.csv"),
        &["part", "mode", "scheduler"],
    );
    assert!(h.contains(&"true_p_ci95".to_string()));
    assert!(
        h.contains(&"engine_hash".to_string()),
        "summaries are stamped"
    );
    assert_eq!(summary.len(), 2 * (2 + k * 4));
    parse_csv(
        &out.join("curves_summary.csv"),
        &["part", "mode", "scheduler"],
    );

    // Per-frame records: one file per run, one row per frame, the audit's columns filled.
    let frames = out.join("frames");
    let n_files = std::fs::read_dir(&frames).expect("frames dir").count();
    assert_eq!(n_files, res.runs.len());
    let (h, rows) = parse_csv(&frames.join("table_n30_s1_zero_round-robin.csv"), &[]);
    assert_eq!(rows.len(), 6);
    let col = |name: &str| h.iter().position(|c| c == name).expect("column");
    for r in &rows {
        assert_eq!(r[col("sphere_tests")], "0", "interrupt at 0 does no test");
        assert!(!r[col("true_p")].is_empty(), "audit on: true P present");
        assert!(!r[col("p")].is_empty(), "scripted gaze: P present");
    }
    let (_, rows) = parse_csv(&frames.join("table_n30_s2_exact_round-robin.csv"), &[]);
    assert!(rows.iter().all(|r| r[col("deemed")] == "0"));

    let md = std::fs::read_to_string(out.join("table_report.md")).expect("report");
    assert!(md.contains("T exact / interrupted"), "{md}");
    // A budget that covers every exact frame is marked, and out of the headlines.
    assert!(
        md.contains("| 10 | tests=1000000 (never interrupts) |"),
        "{md}"
    );
    assert!(
        md.contains("- N = 10, tests=1000000: never interrupts"),
        "{md}"
    );
    assert!(
        !md.contains("- N = 10, tests=200: never interrupts"),
        "{md}"
    );
    let md = std::fs::read_to_string(out.join("f1_report.md")).expect("report");
    assert!(md.contains("| sorted-sequential |"), "{md}");
    let (_, f1_runs) = parse_csv(&out.join("f1_runs.csv"), &["part", "mode", "scheduler"]);
    assert_eq!(f1_runs.len(), 2 * 2 * 5);
    let md = std::fs::read_to_string(out.join("curves_report.md")).expect("report");
    assert!(md.contains("expected-gain /"), "{md}");
    assert!(md.contains("closed loop"), "{md}");

    // The open-loop part: every scheduler of the condition and the clairvoyant bound at every
    // budget, the bound's true P never above a scheduler's.
    let (h, rows) = parse_csv(
        &out.join("open_loop_summary.csv"),
        &["condition", "budget", "scheduler"],
    );
    let col = |name: &str| h.iter().position(|c| c == name).expect("column");
    let (budget, sched, tp) = (col("budget"), col("scheduler"), col("true_p"));
    for b in ["tests=0.05", "tests=0.3"] {
        let at: Vec<&Vec<String>> = rows.iter().filter(|r| r[budget] == b).collect();
        let bound = at
            .iter()
            .find(|r| r[sched] == "clairvoyant")
            .map(|r| r[tp].parse::<f64>().expect("number"))
            .expect("clairvoyant row");
        assert!(at.len() > 2, "{b}: {at:?}");
        for r in &at {
            let p: f64 = r[tp].parse().expect("number");
            assert!(
                bound <= p * (1.0 + 1e-9) + 1e-12,
                "{b}: bound {bound} above {r:?}"
            );
        }
    }
    let report = res.open_loop_report.as_deref().expect("open-loop report");
    assert!(report.contains("| clairvoyant |"), "{report}");
    assert!(out.join("open_loop_report.md").is_file());
    // The grid ran on the same frames and says where each scheduler halves P.
    let grid = res.grid_report.as_deref().expect("grid report");
    assert!(grid.contains("halves round-robin's true P"), "{grid}");
    assert!(grid.contains("priority-only@1deg"), "{grid}");
    let (_, rows) = parse_csv(
        &out.join("grid").join("open_loop_summary.csv"),
        &["condition", "budget", "scheduler"],
    );
    assert!(rows.iter().any(|r| r[0] == "150"), "{rows:?}");
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn deterministic_budgets_replay_exactly() {
    let mut a = tiny(out_dir("det-a"));
    a.open_loop = None;
    a.paper_ms_scale = None;
    a.table = false;
    a.frame_csv = false;
    let mut b = a.clone();
    b.out = out_dir("det-b");
    b.jobs = 1;
    let ra = run_study(&a).expect("a");
    let rb = run_study(&b).expect("b");
    assert_eq!(ra.runs.len(), rb.runs.len());
    for (x, y) in ra.runs.iter().zip(&rb.runs) {
        assert_eq!(x.spec, y.spec);
        assert_eq!(x.true_p.mean().to_bits(), y.true_p.mean().to_bits());
        assert_eq!(x.tests.mean().to_bits(), y.tests.mean().to_bits());
    }
    let _ = std::fs::remove_dir_all(&a.out);
    let _ = std::fs::remove_dir_all(&b.out);
}

#[test]
fn a_bad_gaze_trace_is_an_error_not_a_panic() {
    let out = out_dir("badgaze");
    let mut cfg = tiny(out.clone());
    cfg.gaze = GazeSpec::Csv(out.join("does-not-exist.csv"));
    let err = run_study(&cfg).expect_err("missing trace");
    assert!(err.to_string().contains("does-not-exist.csv"), "{err}");
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn recorded_trace_drives_a_study() {
    let out = out_dir("recorded");
    std::fs::create_dir_all(&out).expect("dir");
    let trace = out.join("trace.csv");
    let mut csv = String::from("# synthetic trace, screen 1920x1080 px\nt_s,xpos,ypos,ps\n");
    for i in 0..200 {
        let t = f64::from(i) * 0.001;
        if i % 50 == 10 {
            csv.push_str(&format!("{t:.3},,,\n"));
        } else {
            csv.push_str(&format!("{t:.3},{},{},1000\n", 900 + i, 500));
        }
    }
    std::fs::write(&trace, csv).expect("write trace");
    let mut cfg = tiny(out.clone());
    cfg.gaze = GazeSpec::Csv(trace);
    cfg.curves = None;
    cfg.open_loop = None;
    cfg.ns = vec![10];
    let res = run_study(&cfg).expect("study runs");
    assert!(res.runs.iter().all(|r| r.p.count() > 0));
    let _ = std::fs::remove_dir_all(&out);
}
