//! The tiny study run whole (one shard) and as three shards, each shard its own process as on a
//! cluster, then merged: every deterministic cell equal bit for bit, every file of the merge equal
//! once the wall clock's readings are set aside, and a merge with a shard missing or doubled
//! refused with the cells named.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use serde_json::Value;

const BIN: &str = env!("CARGO_BIN_EXE_foveal-bench");

fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("foveal-shards-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

fn run(args: &[&str]) -> Output {
    Command::new(BIN)
        .args(args)
        // The index must come from the flags here, not from a scheduler running the tests.
        .env_remove("JOB_COMPLETION_INDEX")
        .env_remove("SLURM_ARRAY_TASK_ID")
        .env_remove("FOVEAL_SHARDS")
        .output()
        .expect("foveal-bench runs")
}

fn ok(args: &[&str]) {
    let out = run(args);
    assert!(
        out.status.success(),
        "foveal-bench {args:?} failed:\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

fn shard(i: u32, n: u32, dir: &Path) -> std::process::Child {
    Command::new(BIN)
        .args(["study", "--tiny", "--no-frames", "--jobs", "1", "--shard"])
        .arg(format!("{i}/{n}"))
        .arg("--out")
        .arg(dir)
        .env_remove("JOB_COMPLETION_INDEX")
        .env_remove("SLURM_ARRAY_TASK_ID")
        .env_remove("FOVEAL_SHARDS")
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("shard starts")
}

fn wait(child: std::process::Child, what: &str) {
    let out = child.wait_with_output().expect("shard ends");
    assert!(
        out.status.success(),
        "{what} failed:\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

fn partials(dir: &Path) -> Vec<(PathBuf, Value)> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir)
        .expect("partials dir")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.to_string_lossy().ends_with(".partial.json"))
        .collect();
    v.sort();
    v.into_iter()
        .map(|p| {
            let text = std::fs::read_to_string(&p).expect("partial readable");
            let value: Value = serde_json::from_str(&text).expect("partial is JSON");
            (p, value)
        })
        .collect()
}

/// Every cell record of the partials, by cell name.
fn records(ps: &[(PathBuf, Value)]) -> std::collections::BTreeMap<String, Value> {
    let mut m = std::collections::BTreeMap::new();
    for (_, p) in ps {
        for key in ["closed_loop", "open_loop"] {
            for r in p[key].as_array().expect("records") {
                let cell = r["cell"].as_str().expect("cell name").to_owned();
                assert!(m.insert(cell.clone(), r.clone()).is_none(), "{cell} twice");
            }
        }
    }
    m
}

/// A float of a record, exactly as written ("NaN" and the infinities are strings).
fn bits(v: &Value) -> u64 {
    match v {
        Value::Number(n) => n.as_f64().expect("f64").to_bits(),
        Value::String(s) if s == "NaN" => f64::NAN.to_bits(),
        other => panic!("not a float: {other}"),
    }
}

/// The fields of a record that a wall clock sets (T and the narrow phase's time, a cell's wall
/// time, the open loop's wall-clock base), or that say how the cells were grouped into runs.
const CLOCK: [&str; 7] = [
    "t_ms",
    "narrow_ms",
    "wall_s",
    "run_cells",
    "exact_narrow_ms",
    "base_range_ms",
    "speed_range_ns",
];

/// Compare two values, floats by their bits, naming the path of the first difference.
fn same(a: &Value, b: &Value, path: &str) {
    match (a, b) {
        (Value::Number(_), Value::Number(_)) => {
            assert_eq!(bits(a), bits(b), "{path}: {a} against {b}");
        }
        (Value::Array(x), Value::Array(y)) => {
            assert_eq!(x.len(), y.len(), "{path}: lengths");
            for (k, (p, q)) in x.iter().zip(y).enumerate() {
                same(p, q, &format!("{path}[{k}]"));
            }
        }
        (Value::Object(x), Value::Object(y)) => {
            assert_eq!(x.len(), y.len(), "{path}: fields");
            for (k, p) in x {
                same(p, &y[k], &format!("{path}.{k}"));
            }
        }
        _ => assert_eq!(a, b, "{path}"),
    }
}

/// `r` without what a wall clock set (see [`CLOCK`]; an open-loop cell's prioritisation time;
/// `None` for a closed-loop run under a wall-clock budget, all of which the clock sets). None of
/// the tiny protocol's open-loop budgets is wall clock.
fn without_clock(cell: &str, r: &Value) -> Option<Value> {
    if cell.contains("_ms-") {
        return None;
    }
    let mut r = r.clone();
    let obj = r.as_object_mut()?;
    for k in CLOCK {
        obj.remove(k);
    }
    if let Some(cells) = obj.get_mut("cells").and_then(Value::as_array_mut) {
        for b in cells {
            for x in b.as_array_mut()? {
                x.as_array_mut()?.truncate(2);
            }
        }
    }
    Some(r)
}

/// Give the records of `ps` the wall-clock readings of the same cells in `from`.
fn take_clock(ps: &mut [(PathBuf, Value)], from: &std::collections::BTreeMap<String, Value>) {
    for (_, p) in ps.iter_mut() {
        for key in ["closed_loop", "open_loop"] {
            for r in p[key].as_array_mut().expect("records") {
                let cell = r["cell"].as_str().expect("cell").to_owned();
                let src = &from[&cell];
                if cell.contains("_ms-") {
                    *r = src.clone();
                    continue;
                }
                for k in CLOCK {
                    if src.get(k).is_some() {
                        r[k] = src[k].clone();
                    }
                }
                let budgets = src["cells"].as_array().map_or(0, Vec::len);
                for bi in 0..budgets {
                    let scheds = src["cells"][bi].as_array().map_or(0, Vec::len);
                    for si in 0..scheds {
                        r["cells"][bi][si][2] = src["cells"][bi][si][2].clone();
                    }
                }
            }
        }
    }
}

/// Every file under `dir`, by path relative to it.
fn tree(dir: &Path) -> std::collections::BTreeMap<PathBuf, Vec<u8>> {
    fn walk(root: &Path, d: &Path, out: &mut std::collections::BTreeMap<PathBuf, Vec<u8>>) {
        for e in std::fs::read_dir(d).expect("dir").flatten() {
            let p = e.path();
            if p.is_dir() {
                walk(root, &p, out);
            } else {
                let rel = p.strip_prefix(root).expect("under root").to_owned();
                out.insert(rel, std::fs::read(&p).expect("file"));
            }
        }
    }
    let mut m = std::collections::BTreeMap::new();
    walk(dir, dir, &mut m);
    m
}

/// The lines of a merged report that are the shards' stamp: their load averages and wall time.
fn is_stamp(line: &str) -> bool {
    // The machine's load, and the command that wrote the report (each merge names its inputs).
    line.starts_with("Load average at start:") || line.starts_with("Study run at commit")
}

#[test]
fn three_shards_merge_to_the_single_machine_run() {
    let root = scratch("equal");
    let (one, three) = (root.join("one"), root.join("three"));
    // The three shards run at once, as a cluster's tasks do; the whole run beside them.
    let whole = shard(0, 1, &one);
    let tasks: Vec<_> = (0..3).map(|i| shard(i, 3, &three)).collect();
    wait(whole, "shard 0/1");
    for (i, t) in tasks.into_iter().enumerate() {
        wait(t, &format!("shard {i}/3"));
    }
    let p1 = partials(&one);
    let mut p3 = partials(&three);
    assert_eq!(p1.len(), 1);
    assert_eq!(p3.len(), 3);
    for (_, p) in p1.iter().chain(&p3) {
        assert_eq!(p["format"], "foveal-bench partial 1");
        assert_eq!(p["command"], "study");
        assert_eq!(p["protocol_hash"], p1[0].1["protocol_hash"]);
        assert_eq!(p["engine_hash"], p1[0].1["engine_hash"]);
        assert_eq!(p["protocol"]["tiny"], true);
    }
    // Every shard has work: the cells are spread, not piled on one.
    let counts: Vec<usize> = p3
        .iter()
        .map(|(_, p)| p["cells"].as_array().map_or(0, Vec::len))
        .collect();
    assert!(counts.iter().all(|&c| c > 0), "{counts:?}");
    let whole_records = records(&p1);
    let shard_records = records(&p3);
    assert_eq!(
        whole_records.keys().collect::<Vec<_>>(),
        shard_records.keys().collect::<Vec<_>>()
    );
    // Every cell that no wall clock touches: equal bit for bit.
    let mut compared = 0;
    for (cell, r) in &whole_records {
        if let (Some(a), Some(b)) = (
            without_clock(cell, r),
            without_clock(cell, &shard_records[cell]),
        ) {
            same(&a, &b, cell);
            compared += 1;
        }
    }
    assert!(compared > 80, "{compared} cells compared");
    assert!(whole_records.keys().any(|c| c.starts_with("open-loop_")));

    // Merged, the shards' files are the whole run's once the wall clock's readings are the same:
    // every line not from a wall clock is equal. Only the stamp line (each shard's load average)
    // is set aside.
    take_clock(&mut p3, &whole_records);
    let patched = root.join("three-patched");
    std::fs::create_dir_all(&patched).expect("dir");
    for (path, p) in &p3 {
        let name = path.file_name().expect("file name");
        std::fs::write(patched.join(name), p.to_string()).expect("write");
    }
    let (m1, m3, m3raw) = (root.join("m1"), root.join("m3"), root.join("m3-raw"));
    let one_s = one.to_string_lossy().into_owned();
    let patched_s = patched.to_string_lossy().into_owned();
    ok(&["merge", &one_s, "--out", &m1.to_string_lossy()]);
    ok(&["merge", &patched_s, "--out", &m3.to_string_lossy()]);
    // The shards as written merge too (their clock readings are their own).
    ok(&[
        "merge",
        &three.to_string_lossy(),
        "--out",
        &m3raw.to_string_lossy(),
    ]);
    let (a, b) = (tree(&m1), tree(&m3));
    assert_eq!(a.keys().collect::<Vec<_>>(), b.keys().collect::<Vec<_>>());
    for name in [
        "table_report.md",
        "curves_report.md",
        "open_loop_report.md",
        "grid/open_loop_report.md",
        "table_runs.csv",
        "figures/fig4_time.svg",
    ] {
        assert!(a.contains_key(Path::new(name)), "merge wrote no {name}");
    }
    let mut files = 0;
    for (name, x) in &a {
        if name == Path::new("cells.csv") {
            continue; // which shard ran each cell: differs by design
        }
        let y = &b[name];
        if name == Path::new("stamp.json") {
            // The same engine and fingerprint; the command that wrote each differs by design.
            let fields = |t: &[u8]| {
                let v: serde_json::Value = serde_json::from_slice(t).expect("stamp parses");
                (v["engine_hash"].clone(), v["fingerprint"].clone())
            };
            assert_eq!(fields(x), fields(y));
            files += 1;
            continue;
        }
        if name.extension().is_some_and(|e| e == "md" || e == "csv") {
            let (x, y) = (String::from_utf8_lossy(x), String::from_utf8_lossy(y));
            let xs: Vec<&str> = x.lines().filter(|l| !is_stamp(l)).collect();
            let ys: Vec<&str> = y.lines().filter(|l| !is_stamp(l)).collect();
            assert_eq!(xs.len(), ys.len(), "{}: line count", name.display());
            for (k, (l, m)) in xs.iter().zip(&ys).enumerate() {
                assert_eq!(l, m, "{} line {}", name.display(), k + 1);
            }
        } else {
            assert!(x == y, "{} differs", name.display());
        }
        files += 1;
    }
    assert!(files > 20, "{files} files compared");
    let _ = std::fs::remove_dir_all(&root);
}

#[test]
fn a_merge_names_the_cells_of_a_missing_or_doubled_shard() {
    let root = scratch("refuse");
    let (one, three) = (root.join("one"), root.join("three"));
    let tasks: Vec<_> = (0..3).map(|i| shard(i, 3, &three)).collect();
    let whole = shard(0, 1, &one);
    for (i, t) in tasks.into_iter().enumerate() {
        wait(t, &format!("shard {i}/3"));
    }
    wait(whole, "shard 0/1");
    let ps = partials(&three);
    let cells_of = |k: usize| -> Vec<String> {
        ps[k].1["cells"]
            .as_array()
            .expect("cells")
            .iter()
            .map(|c| c.as_str().expect("name").to_owned())
            .collect()
    };
    let out = root.join("merged");
    let out_s = out.to_string_lossy().into_owned();

    // Shard 1 of 3 missing: refused, naming the shard and its cells.
    let (a, c) = (
        ps[0].0.to_string_lossy().into_owned(),
        ps[2].0.to_string_lossy().into_owned(),
    );
    let r = run(&["merge", &a, &c, "--out", &out_s]);
    assert!(!r.status.success(), "a merge without shard 1/3 succeeded");
    let err = String::from_utf8_lossy(&r.stderr);
    assert!(err.contains("no partial of shard 1/3"), "{err}");
    let missing = cells_of(1);
    assert!(
        err.contains(&format!("{} of ", missing.len())),
        "{} cells missing: {err}",
        missing.len()
    );
    for cell in missing.iter().take(5) {
        assert!(err.contains(cell.as_str()), "{cell} not named: {err}");
    }
    assert!(
        !out.join("table_report.md").exists(),
        "a refused merge wrote"
    );

    // The whole run's partial beside the shards': every cell doubled, named with both files.
    let whole = one.join("shard-0000-of-0001.partial.json");
    let r = run(&[
        "merge",
        &three.to_string_lossy(),
        &whole.to_string_lossy(),
        "--out",
        &out_s,
    ]);
    assert!(
        !r.status.success(),
        "a merge with every cell twice succeeded"
    );
    let err = String::from_utf8_lossy(&r.stderr);
    let all = cells_of(0).len() + cells_of(1).len() + cells_of(2).len();
    assert!(
        err.contains(&format!("{all} cells in more than one partial")),
        "{err}"
    );
    // The first cell of the protocol, the first the message names.
    assert!(err.contains("table_n10_s1_exact_round-robin"), "{err}");
    assert!(err.contains("shard-0000-of-0001.partial.json"), "{err}");

    // A shard run twice (its file copied): its cells doubled, the others fine.
    let copy = root.join("copy.partial.json");
    std::fs::copy(&ps[2].0, &copy).expect("copy");
    let r = run(&[
        "merge",
        &three.to_string_lossy(),
        &copy.to_string_lossy(),
        "--out",
        &out_s,
    ]);
    let err = String::from_utf8_lossy(&r.stderr);
    assert!(!r.status.success() && err.contains("cells in more than one partial"));
    assert!(!err.contains("missing"), "{err}");
    for cell in cells_of(2).iter().take(5) {
        assert!(err.contains(cell.as_str()), "{cell} not named: {err}");
    }

    // Another protocol's partial is refused by name.
    let other = root.join("other");
    ok(&[
        "study",
        "--tiny",
        "--no-frames",
        "--seeds",
        "1",
        "--no-open-loop",
        "--shard",
        "0/1",
        "--out",
        &other.to_string_lossy(),
    ]);
    let r = run(&[
        "merge",
        &a,
        &other
            .join("shard-0000-of-0001.partial.json")
            .to_string_lossy(),
        "--out",
        &out_s,
    ]);
    let err = String::from_utf8_lossy(&r.stderr);
    assert!(!r.status.success() && err.contains("ran protocol"), "{err}");
    let _ = std::fs::remove_dir_all(&root);
}

#[test]
fn the_shard_index_comes_from_an_indexed_job_or_an_array_task() {
    let root = scratch("env");
    let k8s = Command::new(BIN)
        .args(["study", "--tiny", "--no-frames", "--no-open-loop", "--out"])
        .arg(root.join("k8s"))
        .env("JOB_COMPLETION_INDEX", "2")
        .env("FOVEAL_SHARDS", "3")
        .env_remove("SLURM_ARRAY_TASK_ID")
        .output()
        .expect("runs");
    assert!(
        k8s.status.success(),
        "{}",
        String::from_utf8_lossy(&k8s.stderr)
    );
    assert!(root.join("k8s/shard-0002-of-0003.partial.json").is_file());
    let slurm = Command::new(BIN)
        .args(["study", "--tiny", "--no-frames", "--no-open-loop", "--out"])
        .arg(root.join("slurm"))
        .env_remove("JOB_COMPLETION_INDEX")
        .env_remove("FOVEAL_SHARDS")
        .env("SLURM_ARRAY_TASK_ID", "4")
        .env("SLURM_ARRAY_TASK_MIN", "1")
        .env("SLURM_ARRAY_TASK_COUNT", "4")
        .output()
        .expect("runs");
    assert!(
        slurm.status.success(),
        "{}",
        String::from_utf8_lossy(&slurm.stderr)
    );
    assert!(root.join("slurm/shard-0003-of-0004.partial.json").is_file());
    // An index past the count is refused with the limit.
    let bad = run(&["study", "--tiny", "--shard", "3/3"]);
    assert!(!bad.status.success());
    assert!(String::from_utf8_lossy(&bad.stderr).contains("0 to 2 of 3"));
    let _ = std::fs::remove_dir_all(&root);
}

#[test]
fn a_sharded_open_loop_grid_merges_to_the_whole_one() {
    use foveal_bench::open_loop::{Budget, OpenLoopConfig, run_and_write};
    use foveal_bench::{Shard, merge_open_loop, run_open_loop_shard};
    let root = scratch("grid");
    let mut cfg = OpenLoopConfig::grid();
    cfg.ns = vec![150];
    cfg.seeds = vec![1, 2];
    cfg.frames = vec![(150, 3)];
    cfg.warmup = 5;
    cfg.timing_frames = 1;
    cfg.budgets = vec![Budget::Tests(0.05), Budget::Tests(0.3)];
    cfg.conditions.truncate(3);
    cfg.out = root.join("whole");
    run_and_write(&cfg).expect("whole run");
    let parts = root.join("parts");
    for i in 0..4 {
        let shard = Shard::new(i, 4).expect("shard");
        let p = run_open_loop_shard(&cfg, shard, Value::Null).expect("shard runs");
        p.write(&parts).expect("partial written");
    }
    let partials = foveal_bench::shard::read_partials(&[parts]).expect("partials");
    assert_eq!(partials.len(), 4);
    let mut merged_cfg = cfg.clone();
    merged_cfg.out = root.join("merged");
    merge_open_loop(&merged_cfg, &partials).expect("merge");
    // Every summary row equal but its last column, the prioritisation's wall-clock time.
    let rows = |dir: &Path| -> Vec<String> {
        std::fs::read_to_string(dir.join("open_loop_summary.csv"))
            .expect("summary")
            .lines()
            .map(|l| l.rsplit_once(',').map_or(l, |(a, _)| a).to_owned())
            .collect()
    };
    let (a, b) = (rows(&cfg.out), rows(&merged_cfg.out));
    assert!(a.len() > 20, "{} rows", a.len());
    assert_eq!(a, b);
    let _ = std::fs::remove_dir_all(&root);
}
