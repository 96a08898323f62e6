//! `foveal-bench scale` end to end at a small N: every configuration runs in its own child process
//! of the real binary and comes back as a table row with finite positive times and a peak RSS.

use std::path::PathBuf;

use foveal_bench::scale::{Mode, ScaleConfig, csv, markdown, run};

#[test]
fn quick_protocol_gives_a_row_per_configuration() {
    let out_dir = std::env::temp_dir().join(format!("foveal-bench-scale-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&out_dir);
    let cfg = ScaleConfig {
        ns: vec![2_000],
        threads: vec![1, 2],
        frames: Some(3),
        warmup: Some(1),
        quick: true,
        out: out_dir.clone(),
        ..ScaleConfig::default()
    };
    let exe = PathBuf::from(env!("CARGO_BIN_EXE_foveal-bench"));
    let out = run(&cfg, &exe, false).expect("scale run");
    assert_eq!(out.results.len(), 4, "exact and budget, 1 and 2 threads");
    for (r, spec) in out.results.iter().zip(cfg.plan()) {
        assert_eq!(r.spec, spec);
        for v in [
            r.step_p50_ms,
            r.step_p99_ms,
            r.step_mean_ms,
            r.step_ns_per_body,
        ] {
            assert!(v.is_finite() && v > 0.0, "{r:?}");
        }
        assert!(r.step_p99_ms >= r.step_p50_ms);
        assert!(r.peak_rss_kib > 0, "{r:?}");
        assert!((0.0..=1.0).contains(&r.foveal_exact_share));
        let shares: f64 = r.phase_share.iter().map(|(_, s)| s).sum();
        assert!(shares > 0.0 && shares <= 1.0 + 1e-9, "{shares}");
    }
    assert!(
        out.results
            .iter()
            .any(|r| r.spec.mode == Mode::BudgetMs(4.0))
    );

    let md = markdown(&out);
    // The processor the figures belong to is named above the table.
    assert!(out.machine.logical >= 1);
    let machine = format!("Machine: {}.", out.machine);
    assert!(md.contains(&machine), "{md}");
    let rows = md.lines().filter(|l| l.starts_with("| 2,000 |")).count();
    assert_eq!(rows, 4, "{md}");
    let table = csv(&out.results);
    assert_eq!(table.lines().count(), 5, "{table}");
    for f in &out.files {
        assert!(f.exists(), "{}", f.display());
    }
    let _ = std::fs::remove_dir_all(&out_dir);
}

/// With two rounds every configuration runs twice, round after round: one row each (its median
/// run), its spread in the table, and every run with its round in the CSV.
#[test]
fn repeated_rounds_report_each_configuration_once_with_its_spread() {
    let out_dir =
        std::env::temp_dir().join(format!("foveal-bench-scale-rounds-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&out_dir);
    let cfg = ScaleConfig {
        ns: vec![2_000],
        threads: vec![1],
        frames: Some(3),
        warmup: Some(1),
        quick: true,
        repeat: 2,
        out: out_dir.clone(),
        ..ScaleConfig::default()
    };
    let exe = PathBuf::from(env!("CARGO_BIN_EXE_foveal-bench"));
    let out = run(&cfg, &exe, false).expect("scale run");
    let plan = cfg.plan();
    assert_eq!(out.results.len(), plan.len());
    assert_eq!(out.runs.len(), 2 * plan.len());
    let rounds: Vec<u32> = out.runs.iter().map(|r| r.round).collect();
    assert_eq!(rounds, [1, 1, 2, 2]);
    for ((row, spec), spread) in out.results.iter().zip(&plan).zip(&out.spreads) {
        assert_eq!(&row.spec, spec);
        let spread = spread.expect("two runs: a spread");
        assert_eq!(spread.runs, 2);
        assert!(spread.p50[0] <= row.step_p50_ms && row.step_p50_ms <= spread.p50[1]);
        // The slower of two is the row.
        assert_eq!(row.step_p50_ms, spread.p50[1]);
    }
    let md = markdown(&out);
    assert!(md.contains("2 runs: p50 / p99 least-greatest (ms)"), "{md}");
    assert_eq!(md.lines().filter(|l| l.starts_with("| 2,000 |")).count(), 2);
    let table = std::fs::read_to_string(out_dir.join("scale.csv")).expect("scale.csv");
    assert_eq!(table.lines().count(), 5, "{table}");
    let header: Vec<&str> = table
        .lines()
        .next()
        .map_or(Vec::new(), |h| h.split(',').collect());
    for column in ["round", "settled_per_ms", "exact_fit_share"] {
        assert!(header.contains(&column), "{column} in {header:?}");
    }
    let _ = std::fs::remove_dir_all(&out_dir);
}
