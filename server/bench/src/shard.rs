//! Sharded runs: a protocol's cells split over the workers of a cluster (Kubernetes indexed Jobs,
//! Slurm job arrays), each worker writing a self-describing partial result, and the partials
//! merged into the files one machine would have written.
//!
//! Why cells and not frames: a cell is the unit whose result does not depend on any other cell
//! (one closed-loop run; one (N, seed) of the open loop, whose parts share its frames), so a
//! shard's results are exactly those of the same cells in a single run, and under sphere-test
//! budgets bit for bit.
//!
//! Every shard computes the same assignment without talking to the others: the cells' costs are
//! estimated from the protocol alone ([`closed_loop_cost_s`], [`open_loop_cost_s`]; measured
//! per-frame costs, see docs/DEPLOY.md), sorted longest first, and each given to the shard with the
//! least estimated work so far (the LPT rule; ties go to the lower index). A partial names its
//! protocol (the flags it was run with and their hash), the engine sources it ran, its shard and
//! its cells, so that a merge can refuse partials of another protocol or engine and name the cells
//! missing or run twice.

use std::collections::BTreeMap;
use std::fmt;
use std::path::{Path, PathBuf};

use serde::de::{self, Visitor};
use serde::{Deserialize, Deserializer, Serialize, Serializer};

use crate::open_loop::{self, Cell, OpenLoopConfig, RunResult, RunStamp};
use crate::protocol::{Mode, RunSpec, StudyConfig};
use crate::runner::RunSummary;
use crate::stats::Accum;

/// Hash of the sources that compute a cell (the engine, the gaze crate and this bench), taken by
/// the build script: shards built from different sources may disagree on a cell, so a merge
/// refuses to mix them.
pub const ENGINE_SOURCE_HASH: &str = env!("FOVEAL_ENGINE_SOURCE_HASH");

pub use crate::shard_error::{PARTIAL_FORMAT, PARTIAL_SUFFIX, ShardError};

/// One shard of `count`: index `index`, numbered from 0 as Kubernetes' `JOB_COMPLETION_INDEX` is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Shard {
    /// This shard, 0 to `count - 1`.
    pub index: u32,
    /// Shards in all.
    pub count: u32,
}

impl fmt::Display for Shard {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}

impl Shard {
    /// The whole protocol on one machine.
    pub const WHOLE: Self = Self { index: 0, count: 1 };

    /// Shard `index` of `count`, refused unless `index < count`.
    pub fn new(index: u64, count: u64) -> Result<Self, ShardError> {
        if count == 0 {
            return Err(ShardError::ZeroCount);
        }
        if index >= count {
            return Err(ShardError::OutOfRange { index, count });
        }
        match (u32::try_from(index), u32::try_from(count)) {
            (Ok(index), Ok(count)) => Ok(Self { index, count }),
            _ => Err(ShardError::OutOfRange { index, count }),
        }
    }

    /// `I/N`.
    pub fn parse(value: &str) -> Result<Self, ShardError> {
        let syntax = || ShardError::Syntax {
            value: value.to_owned(),
        };
        let (i, n) = value.split_once('/').ok_or_else(syntax)?;
        let i: u64 = i.trim().parse().map_err(|_| syntax())?;
        let n: u64 = n.trim().parse().map_err(|_| syntax())?;
        Self::new(i, n)
    }

    /// The shard a scheduler's task is, when `--shard` is not given: the index from
    /// `JOB_COMPLETION_INDEX` (Kubernetes indexed Jobs) or else `SLURM_ARRAY_TASK_ID` less
    /// `SLURM_ARRAY_TASK_MIN` (Slurm arrays, so `--array=1-8` works as `0-7`); the count from
    /// `count` (`--shards`, `FOVEAL_SHARDS`) or else `SLURM_ARRAY_TASK_COUNT`. `None` when no
    /// index is set: the whole protocol. `env` reads a variable (`std::env::var` in the binary).
    pub fn from_env(
        count: Option<u64>,
        env: impl Fn(&str) -> Option<String>,
    ) -> Result<Option<Self>, ShardError> {
        let num = |var: &'static str| -> Result<Option<u64>, ShardError> {
            match env(var) {
                None => Ok(None),
                Some(v) if v.trim().is_empty() => Ok(None),
                Some(v) => v
                    .trim()
                    .parse()
                    .map(Some)
                    .map_err(|_| ShardError::Env { var, value: v }),
            }
        };
        let (var, index) = if let Some(i) = num("JOB_COMPLETION_INDEX")? {
            ("JOB_COMPLETION_INDEX", i)
        } else if let Some(i) = num("SLURM_ARRAY_TASK_ID")? {
            let min = num("SLURM_ARRAY_TASK_MIN")?.unwrap_or(0);
            ("SLURM_ARRAY_TASK_ID", i.saturating_sub(min))
        } else {
            return match count {
                Some(count) => Err(ShardError::CountWithoutIndex { count }),
                None => Ok(None),
            };
        };
        let count = match count {
            Some(c) => c,
            None if var == "SLURM_ARRAY_TASK_ID" => {
                num("SLURM_ARRAY_TASK_COUNT")?.ok_or(ShardError::MissingCount { var })?
            }
            None => return Err(ShardError::MissingCount { var }),
        };
        Self::new(index, count).map(Some)
    }

    /// The partial's file name: `shard-0003-of-0008.partial.json`.
    pub fn file_name(&self) -> String {
        format!(
            "shard-{:04}-of-{:04}{PARTIAL_SUFFIX}",
            self.index, self.count
        )
    }
}

/// What a cell runs.
#[derive(Debug, Clone, PartialEq)]
pub enum CellKind {
    /// A closed-loop run of the study's plan (its index in [`StudyConfig::plan`]).
    ClosedLoop(usize),
    /// One condition of one open-loop part at one (N, seed): every scheduler and budget of the
    /// condition on that scene's frames. Cells of the same (N, seed) in one shard share their
    /// frames (one exact run, one set of truths).
    OpenLoop {
        /// Bodies.
        n: u32,
        /// Seed.
        seed: u64,
        /// The part (the comparison, then the grid).
        part: usize,
        /// The condition within the part.
        condition: usize,
    },
}

/// One cell of a protocol: its name, its estimated cost and what it runs.
#[derive(Debug, Clone, PartialEq)]
pub struct CellSpec {
    /// The name partials and merge errors use: the closed-loop run's file stem
    /// (`table_n500_s3_fraction-0.1_priced`) or `open-loop_n10000_s2_p1_c03` (part 1, the grid;
    /// its condition 3).
    pub id: String,
    /// Estimated seconds on one core of a 2-core reference machine, run alone (see
    /// docs/DEPLOY.md).
    pub cost_s: f64,
    /// What it runs.
    pub kind: CellKind,
    /// The cells it is cheaper to run with (one open-loop scene's conditions share its frames).
    pub group: Option<CellGroup>,
    /// Run on the shard's one timing thread, in order (the table's closed-loop runs, whose T is
    /// measured undisturbed by a sibling run); the others share the shard's `--jobs` threads.
    pub serial: bool,
}

/// Cells that cost less together than apart: the conditions of one open-loop (N, seed), which
/// share one exact run and one set of pair truths.
#[derive(Debug, Clone, PartialEq)]
pub struct CellGroup {
    /// The group's name (`open-loop_n10000_s2`).
    pub key: String,
    /// Estimated seconds of all its cells run together.
    pub cost_s: f64,
}

/// Seconds per frame of a closed-loop run (exact, and interrupted: the audit of deemed pairs
/// against the exact narrow phase skipped), at the paper's N: the CPU time of single default-
/// protocol runs of 5,000 frames (plus warm-up and calibration) under the shape truth, seed 1
/// (exact round-robin; priced at 0.1 of the exact cost). docs/DEPLOY.md has the commands.
const CLOSED_FRAME_S: [(f64, f64, f64); 5] = [
    (10.0, 1.54e-5, 7.7e-6),
    (30.0, 5.2e-5, 2.3e-5),
    (100.0, 2.12e-4, 1.04e-4),
    (300.0, 6.66e-4, 3.30e-4),
    (500.0, 1.34e-3, 6.29e-4),
];

/// Seconds per frame per distinct scheduling run of an open-loop cell: fitted, with the overhead
/// below, to the CPU time of four cells of the default protocol each run alone (the grid's
/// F2 C = 0.5 condition, 70 runs, and a model-mismatch condition, 16 runs, at N = 500 and
/// N = 10,000; docs/DEPLOY.md has the commands and figures).
const OPEN_FRAME_S: [(f64, f64); 2] = [(500.0, 2.9e-4), (10_000.0, 5.6e-3)];

/// What a frame of an open-loop cell costs beside its scheduling runs (the exact step, its timing
/// and every pair's truth, each measuring model's weights), in scheduling runs: a cell alone pays
/// it in full, cells of one (N, seed) run together share it. The fit gave 41 at N = 500 and 32
/// at N = 10,000.
const OPEN_FRAME_OVERHEAD_RUNS: f64 = 36.0;

/// Log-log interpolation in `table` (x ascending), extrapolated along the nearest segment.
fn loglog(table: &[(f64, f64)], x: f64) -> f64 {
    let x = x.max(1.0);
    let seg = match table.iter().position(|&(t, _)| t >= x) {
        Some(0) | None if table.len() < 2 => return table.first().map_or(0.0, |&(_, y)| y),
        Some(0) => (table[0], table[1]),
        Some(k) => (table[k - 1], table[k]),
        None => (table[table.len() - 2], table[table.len() - 1]),
    };
    let ((x0, y0), (x1, y1)) = seg;
    let slope = (y1.ln() - y0.ln()) / (x1.ln() - x0.ln());
    (y0.ln() + slope * (x.ln() - x0.ln())).exp()
}

/// Estimated seconds of one closed-loop run of `cfg` (its warm-up and recorded frames).
pub fn closed_loop_cost_s(cfg: &StudyConfig, spec: &RunSpec) -> f64 {
    let exact = spec.mode == Mode::Exact;
    let table: Vec<(f64, f64)> = CLOSED_FRAME_S
        .iter()
        .map(|&(n, e, i)| (n, if exact { e } else { i }))
        .collect();
    f64::from(cfg.warmup_frames + spec.frames) * loglog(&table, f64::from(spec.n))
}

/// Estimated seconds of an open-loop run at `n` of `parts` (conditions cut as wanted): its frames
/// times its distinct scheduling runs, and what every frame costs beside them once per budget
/// (each budget's colliders run on their own replay of the frames).
fn open_loop_run_cost_s(parts: &[&OpenLoopConfig], n: u32) -> f64 {
    let Some(first) = parts.first() else {
        return 0.0;
    };
    let runs = open_loop::schedule_runs(parts) as f64;
    let mut budgets: Vec<open_loop::Budget> = Vec::new();
    for b in parts.iter().flat_map(|p| &p.budgets) {
        if !budgets.contains(b) {
            budgets.push(*b);
        }
    }
    let replays = budgets.len().max(1) as f64;
    let frames = f64::from(first.warmup + first.timing_frames + first.frames_for(n));
    frames * (runs + OPEN_FRAME_OVERHEAD_RUNS * replays) * loglog(&OPEN_FRAME_S, f64::from(n))
}

/// Estimated seconds of one condition `ci` of open-loop part `part` at `n`, run alone.
pub fn open_loop_cost_s(part: &OpenLoopConfig, ci: usize, n: u32) -> f64 {
    let alone = OpenLoopConfig {
        conditions: part.conditions.get(ci).cloned().into_iter().collect(),
        ..part.clone()
    };
    open_loop_run_cost_s(&[&alone], n)
}

/// The open-loop cells of parts run on the same frames: for each (N, seed), each part's
/// conditions in order, grouped by (N, seed).
pub fn open_loop_cells(parts: &[&OpenLoopConfig]) -> Vec<CellSpec> {
    let Some(first) = parts.first() else {
        return Vec::new();
    };
    let mut cells = Vec::new();
    for (n, seed) in open_loop::cells(first) {
        // A part runs only at its own N (the study's grid at N = 500 alone).
        let here: Vec<&OpenLoopConfig> = parts
            .iter()
            .copied()
            .filter(|p| p.ns.contains(&n))
            .collect();
        let group = CellGroup {
            key: format!("open-loop_n{n}_s{seed}"),
            cost_s: open_loop_run_cost_s(&here, n),
        };
        for (pi, p) in parts.iter().enumerate().filter(|(_, p)| p.ns.contains(&n)) {
            for ci in 0..p.conditions.len() {
                cells.push(CellSpec {
                    id: format!("{}_p{pi}_c{ci:02}", group.key),
                    cost_s: open_loop_cost_s(p, ci, n),
                    kind: CellKind::OpenLoop {
                        n,
                        seed,
                        part: pi,
                        condition: ci,
                    },
                    group: Some(group.clone()),
                    serial: false,
                });
            }
        }
    }
    cells
}

/// Refuse a protocol two of whose cells share a name (merge matches cells by name).
pub fn check_unique(cells: &[CellSpec]) -> Result<(), ShardError> {
    let mut seen = std::collections::HashSet::new();
    for c in cells {
        if !seen.insert(c.id.as_str()) {
            return Err(ShardError::DuplicateCell(c.id.clone()));
        }
    }
    Ok(())
}

/// The units of work `cells` are dealt out in over `count` shards, with their estimated seconds:
/// a group's cells together (they share work), except the groups whose splitting shortens the
/// slowest shard: every threshold of group cost is tried (split the groups above it, deal out
/// longest first) and the one with the least slowest shard kept, ties to the one that splits
/// least (the least work). So a few shards keep every scene whole, and many take the long
/// scenes apart. With one shard nothing is split: the whole run is one machine's.
pub fn units(cells: &[CellSpec], count: u32) -> Vec<(Vec<usize>, f64)> {
    let mut whole: Vec<(Vec<usize>, f64)> = Vec::new();
    let mut group_of: BTreeMap<&str, usize> = BTreeMap::new();
    for (k, c) in cells.iter().enumerate() {
        match &c.group {
            Some(g) => match group_of.get(g.key.as_str()) {
                Some(&u) => whole[u].0.push(k),
                None => {
                    group_of.insert(&g.key, whole.len());
                    whole.push((vec![k], g.cost_s));
                }
            },
            None => whole.push((vec![k], c.cost_s)),
        }
    }
    let split_above = |t: f64| -> Vec<(Vec<usize>, f64)> {
        let mut out = Vec::with_capacity(whole.len());
        for (members, cost) in &whole {
            if members.len() > 1 && *cost > t {
                out.extend(members.iter().map(|&k| (vec![k], cells[k].cost_s)));
            } else {
                out.push((members.clone(), *cost));
            }
        }
        out
    };
    let mut thresholds: Vec<f64> = whole
        .iter()
        .filter(|(m, _)| m.len() > 1)
        .map(|(_, c)| *c)
        .collect();
    thresholds.sort_by(|a, b| b.total_cmp(a));
    thresholds.dedup();
    let mut best = whole.clone();
    if count <= 1 {
        return best;
    }
    let wall = |units: &[(Vec<usize>, f64)]| {
        Balance::from_units(cells, units, count).slowest_wall_s(WORKER_THREADS)
    };
    let mut best_wall = wall(&best);
    // Each threshold just below a group cost splits that group and every longer one.
    for t in thresholds.into_iter().map(|c| c * (1.0 - 1e-12)) {
        let units = split_above(t);
        let w = wall(&units);
        if w < best_wall {
            best = units;
            best_wall = w;
        }
    }
    best
}

/// Threads of the worker the split between whole and divided scenes is judged for: the two-core
/// worker the manifests ask for. A constant, not `--jobs`, so that every shard deals the cells
/// out alike whatever its threads.
pub const WORKER_THREADS: usize = 2;

/// The shard of every cell (by position in `cells`) among `count`: the [`units`] longest
/// estimated cost first, each to the shard with the least estimated work so far, ties to the lower
/// index; units of equal cost are taken in their first cell's name order, so every shard
/// computes the same assignment.
pub fn assign(cells: &[CellSpec], count: u32) -> Vec<u32> {
    assign_units(cells, &units(cells, count), count).0
}

/// [`assign`], with each shard's estimated load.
fn assign_units(
    cells: &[CellSpec],
    units: &[(Vec<usize>, f64)],
    count: u32,
) -> (Vec<u32>, Vec<f64>) {
    let count = count.max(1) as usize;
    let name = |u: usize| units[u].0.first().map_or("", |&k| cells[k].id.as_str());
    let mut order: Vec<usize> = (0..units.len()).collect();
    order.sort_by(|&a, &b| {
        units[b]
            .1
            .total_cmp(&units[a].1)
            .then_with(|| name(a).cmp(name(b)))
    });
    let mut load = vec![0.0f64; count];
    let mut out = vec![0u32; cells.len()];
    for u in order {
        let mut best = 0;
        for (s, &l) in load.iter().enumerate() {
            if l < load[best] {
                best = s;
            }
        }
        load[best] += units[u].1;
        for &k in &units[u].0 {
            out[k] = best as u32;
        }
    }
    (out, load)
}

/// The estimated balance of `cells` over `count` shards.
#[derive(Debug, Clone, PartialEq)]
pub struct Balance {
    /// Shards.
    pub count: u32,
    /// Estimated seconds of each shard (core-seconds).
    pub loads: Vec<f64>,
    /// Of each shard's load, the part that runs on its one timing thread.
    pub serial: Vec<f64>,
    /// Each shard's longest unit off the timing thread (one unit runs on one thread).
    pub longest_parallel: Vec<f64>,
    /// Cells of each shard.
    pub cells: Vec<usize>,
    /// Estimated seconds of all the work at this count (groups split apart cost more).
    pub total_s: f64,
    /// The longest unit of work (s): no shard finishes sooner than the one that has it.
    pub longest_unit_s: f64,
}

impl Balance {
    /// Balance `cells` over `count` shards as [`assign`] does.
    pub fn of(cells: &[CellSpec], count: u32) -> Self {
        let count = count.max(1);
        Self::from_units(cells, &units(cells, count), count)
    }

    /// The balance of `units` of `cells` dealt out over `count` shards.
    fn from_units(cells: &[CellSpec], units: &[(Vec<usize>, f64)], count: u32) -> Self {
        let count = count.max(1);
        let (owner, loads) = assign_units(cells, units, count);
        let mut n = vec![0; count as usize];
        for &s in &owner {
            n[s as usize] += 1;
        }
        let mut serial = vec![0.0; count as usize];
        for (c, &s) in cells.iter().zip(&owner) {
            if c.serial {
                serial[s as usize] += c.cost_s;
            }
        }
        let mut longest_parallel = vec![0.0f64; count as usize];
        for (members, cost) in units {
            if let Some(&k) = members.first()
                && !cells[k].serial
            {
                let s = owner[k] as usize;
                longest_parallel[s] = longest_parallel[s].max(*cost);
            }
        }
        Self {
            count,
            total_s: units.iter().map(|(_, s)| s).sum(),
            longest_unit_s: units.iter().map(|(_, s)| *s).fold(0.0, f64::max),
            loads,
            serial,
            longest_parallel,
            cells: n,
        }
    }

    /// The slowest shard's estimated seconds: the wall time of the whole sharded run.
    pub fn slowest_s(&self) -> f64 {
        self.loads.iter().copied().fold(0.0, f64::max)
    }

    /// The slowest shard's wall time (s) on a worker of `jobs` threads: its timing thread's runs
    /// in order, then the rest spread over every thread, but no sooner than its longest unit.
    pub fn slowest_wall_s(&self, jobs: usize) -> f64 {
        let jobs = jobs.max(1) as f64;
        (0..self.loads.len())
            .map(|i| {
                let (l, s) = (self.loads[i], self.serial[i]);
                s + ((l - s) / jobs).max(self.longest_parallel[i])
            })
            .fold(0.0, f64::max)
    }

    /// The slowest shard's share of all the work (1/count at a perfect balance).
    pub fn slowest_share(&self) -> f64 {
        if self.total_s > 0.0 {
            self.slowest_s() / self.total_s
        } else {
            0.0
        }
    }
}

/// A 64-bit FNV-1a hash as 16 hex digits: names a protocol (not a secret; collisions between the
/// few protocols a lab runs are not a concern).
pub fn fnv64(bytes: &[u8]) -> String {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for &b in bytes {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0000_0100_0000_01b3);
    }
    format!("{h:016x}")
}

/// A float written so that reading it back gives the same bits: a JSON number when finite,
/// else `"NaN"`, `"inf"` or `"-inf"` (JSON has no such numbers).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Num(pub f64);

impl Serialize for Num {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let x = self.0;
        if x.is_finite() {
            s.serialize_f64(x)
        } else if x.is_nan() {
            s.serialize_str("NaN")
        } else if x > 0.0 {
            s.serialize_str("inf")
        } else {
            s.serialize_str("-inf")
        }
    }
}

impl<'de> Deserialize<'de> for Num {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl Visitor<'_> for V {
            type Value = Num;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a number, \"NaN\", \"inf\" or \"-inf\"")
            }
            fn visit_f64<E: de::Error>(self, v: f64) -> Result<Num, E> {
                Ok(Num(v))
            }
            fn visit_u64<E: de::Error>(self, v: u64) -> Result<Num, E> {
                Ok(Num(v as f64))
            }
            fn visit_i64<E: de::Error>(self, v: i64) -> Result<Num, E> {
                Ok(Num(v as f64))
            }
            fn visit_str<E: de::Error>(self, v: &str) -> Result<Num, E> {
                match v {
                    "NaN" => Ok(Num(f64::NAN)),
                    "inf" => Ok(Num(f64::INFINITY)),
                    "-inf" => Ok(Num(f64::NEG_INFINITY)),
                    _ => Err(E::invalid_value(de::Unexpected::Str(v), &self)),
                }
            }
        }
        d.deserialize_any(V)
    }
}

fn nums(v: &[f64]) -> Vec<Num> {
    v.iter().map(|&x| Num(x)).collect()
}

fn floats(v: &[Num]) -> Vec<f64> {
    v.iter().map(|x| x.0).collect()
}

/// An [`Accum`]'s running state.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AccumRecord {
    /// Observations.
    pub n: u64,
    /// Running mean.
    pub mean: Num,
    /// Sum of squared deviations.
    pub m2: Num,
}

impl From<&Accum> for AccumRecord {
    fn from(a: &Accum) -> Self {
        let (n, mean, m2) = a.raw();
        Self {
            n,
            mean: Num(mean),
            m2: Num(m2),
        }
    }
}

impl From<AccumRecord> for Accum {
    fn from(r: AccumRecord) -> Self {
        Accum::from_raw(r.n, r.mean.0, r.m2.0)
    }
}

/// One closed-loop run's summary ([`RunSummary`] without its spec, which the protocol gives).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ClosedRecord {
    /// The cell.
    pub cell: String,
    /// Mean exact narrow-phase cost of its (N, seed).
    pub exact_cost: Num,
    /// The sphere-test budget in force.
    pub budget_tests: Option<u64>,
    /// T (ms; wall clock).
    pub t_ms: AccumRecord,
    /// Narrow phase (ms; wall clock).
    pub narrow_ms: AccumRecord,
    /// Estimated Δ.
    pub delta: AccumRecord,
    /// Estimated P.
    pub p: AccumRecord,
    /// True Δ.
    pub true_delta: AccumRecord,
    /// True P.
    pub true_p: AccumRecord,
    /// False positives.
    pub false_positives: AccumRecord,
    /// Deemed pairs.
    pub deemed: AccumRecord,
    /// Candidate pairs.
    pub candidates: AccumRecord,
    /// Real collisions.
    pub real: AccumRecord,
    /// Sphere tests.
    pub tests: AccumRecord,
    /// Frames whose budget ran out.
    pub exhausted: AccumRecord,
    /// Wall time of the run (s).
    pub wall_s: Num,
}

impl ClosedRecord {
    /// The record of `r`, named `cell`.
    pub fn of(cell: &str, r: &RunSummary) -> Self {
        Self {
            cell: cell.to_owned(),
            exact_cost: Num(r.exact_cost),
            budget_tests: r.budget_tests,
            t_ms: (&r.t_ms).into(),
            narrow_ms: (&r.narrow_ms).into(),
            delta: (&r.delta).into(),
            p: (&r.p).into(),
            true_delta: (&r.true_delta).into(),
            true_p: (&r.true_p).into(),
            false_positives: (&r.false_positives).into(),
            deemed: (&r.deemed).into(),
            candidates: (&r.candidates).into(),
            real: (&r.real).into(),
            tests: (&r.tests).into(),
            exhausted: (&r.exhausted).into(),
            wall_s: Num(r.wall_s),
        }
    }

    /// The summary again, its spec from the protocol.
    pub fn summary(&self, spec: RunSpec) -> RunSummary {
        RunSummary {
            spec,
            exact_cost: self.exact_cost.0,
            budget_tests: self.budget_tests,
            t_ms: self.t_ms.into(),
            narrow_ms: self.narrow_ms.into(),
            delta: self.delta.into(),
            p: self.p.into(),
            true_delta: self.true_delta.into(),
            true_p: self.true_p.into(),
            false_positives: self.false_positives.into(),
            deemed: self.deemed.into(),
            candidates: self.candidates.into(),
            real: self.real.into(),
            tests: self.tests.into(),
            exhausted: self.exhausted.into(),
            wall_s: self.wall_s.0,
        }
    }
}

/// One open-loop cell: one condition's results on the frames of one (N, seed), with what the run
/// that computed it measured of the scene (its frames' exact cost and the wall-clock budgets' base).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct OpenRecord {
    /// The cell.
    pub cell: String,
    /// The condition's name (checked against the protocol at merge).
    pub condition: String,
    /// Wall time of the run that computed the cell (s), shared by `run_cells` cells.
    pub wall_s: Num,
    /// Cells computed on the same frames in that run.
    pub run_cells: u32,
    /// Frames recorded.
    pub frames: u32,
    /// Wall-clock budgets' base (ms; wall clock).
    pub exact_narrow_ms: Num,
    /// Its 5-95% range (ms; wall clock).
    pub base_range_ms: [Num; 2],
    /// The base's time per sphere test, 5-95% (ns; wall clock).
    pub speed_range_ns: [Num; 2],
    /// Mean exact sphere tests per frame.
    pub exact_tests: Num,
    /// `[budget][scheduler]`: mean true P, sphere tests, prioritisation ms (wall clock), the
    /// paper's estimated P.
    pub cells: Vec<Vec<[Num; 4]>>,
    /// `[budget]`: mean clairvoyant bound.
    pub bound: Vec<Num>,
    /// `[budget]`: mean sphere tests a frame the bound was taken at (empty in records written
    /// before it was kept).
    #[serde(default)]
    pub bound_tests: Vec<Num>,
    /// Mean true P with every pair deemed.
    pub all_deemed: Num,
    /// Frames counted.
    pub counted: u32,
}

impl OpenRecord {
    /// The record of condition `ci` of `r`, named `cell`.
    pub fn of(cell: &str, condition: &str, r: &RunResult, ci: usize) -> Self {
        Self {
            cell: cell.to_owned(),
            condition: condition.to_owned(),
            wall_s: Num(f64::NAN),
            run_cells: 1,
            frames: r.frames,
            exact_narrow_ms: Num(r.exact_narrow_ms),
            base_range_ms: [Num(r.base_range_ms.0), Num(r.base_range_ms.1)],
            speed_range_ns: [Num(r.speed_range_ns.0), Num(r.speed_range_ns.1)],
            exact_tests: Num(r.exact_tests),
            cells: r.cells.get(ci).map_or_else(Vec::new, |c| {
                c.iter()
                    .map(|b| {
                        b.iter()
                            .map(|x| {
                                [
                                    Num(x.true_p),
                                    Num(x.tests),
                                    Num(x.prioritise_ms),
                                    Num(x.est_p),
                                ]
                            })
                            .collect()
                    })
                    .collect()
            }),
            bound: r.bound.get(ci).map_or_else(Vec::new, |b| nums(b)),
            bound_tests: r.bound_tests.get(ci).map_or_else(Vec::new, |b| nums(b)),
            all_deemed: Num(r.all_deemed.get(ci).copied().unwrap_or(f64::NAN)),
            counted: r.counted.get(ci).copied().unwrap_or(0),
        }
    }

    /// Check the record against condition `ci` of `cfg`.
    fn check(&self, cfg: &OpenLoopConfig, ci: usize) -> Result<(), String> {
        let Some(c) = cfg.conditions.get(ci) else {
            return Err(format!("the protocol has no condition {ci}"));
        };
        if c.name != self.condition {
            return Err(format!(
                "condition {:?} recorded, the protocol's is {:?}",
                self.condition, c.name
            ));
        }
        if self.cells.len() != cfg.budgets.len() || self.bound.len() != cfg.budgets.len() {
            return Err(format!(
                "{} budgets recorded, the protocol has {}",
                self.cells.len(),
                cfg.budgets.len()
            ));
        }
        if let Some(b) = self.cells.iter().find(|b| b.len() != c.schedulers.len()) {
            return Err(format!(
                "{} schedulers recorded, the protocol has {}",
                b.len(),
                c.schedulers.len()
            ));
        }
        Ok(())
    }
}

/// One part's result at one (N, seed) from its conditions' records (in condition order): the
/// scene's figures (exact cost, the wall-clock base) are those of the first condition's run.
fn assemble(n: u32, seed: u64, records: &[&OpenRecord]) -> Option<RunResult> {
    let first = records.first()?;
    Some(RunResult {
        n,
        seed,
        frames: first.frames,
        exact_narrow_ms: first.exact_narrow_ms.0,
        base_range_ms: (first.base_range_ms[0].0, first.base_range_ms[1].0),
        speed_range_ns: (first.speed_range_ns[0].0, first.speed_range_ns[1].0),
        exact_tests: first.exact_tests.0,
        cells: records
            .iter()
            .map(|r| {
                r.cells
                    .iter()
                    .map(|b| {
                        b.iter()
                            .map(|x| Cell {
                                true_p: x[0].0,
                                tests: x[1].0,
                                prioritise_ms: x[2].0,
                                est_p: x[3].0,
                            })
                            .collect()
                    })
                    .collect()
            })
            .collect(),
        bound: records.iter().map(|r| floats(&r.bound)).collect(),
        bound_tests: records.iter().map(|r| floats(&r.bound_tests)).collect(),
        all_deemed: records.iter().map(|r| r.all_deemed.0).collect(),
        counted: records.iter().map(|r| r.counted).collect(),
    })
}

/// A shard's result: self-describing, so that a merge needs nothing else.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Partial {
    /// [`PARTIAL_FORMAT`].
    pub format: String,
    /// The command that ran it: `study` or `open-loop`.
    pub command: String,
    /// The command's protocol flags, from which a merge rebuilds the protocol.
    pub protocol: serde_json::Value,
    /// Hash of the protocol those flags gave (every setting that changes a result).
    pub protocol_hash: String,
    /// [`ENGINE_SOURCE_HASH`] of the build that ran it.
    pub engine_hash: String,
    /// The shard.
    pub shard: Shard,
    /// Every cell of this shard, in the protocol's order.
    pub cells: Vec<String>,
    /// The closed-loop cells' results.
    pub closed_loop: Vec<ClosedRecord>,
    /// The open-loop cells' results.
    pub open_loop: Vec<OpenRecord>,
    /// Load average when the shard started.
    pub load_start: String,
    /// Load average when it ended.
    pub load_end: String,
    /// Wall time of the shard (s).
    pub wall_s: Num,
}

impl Partial {
    /// Write the partial as `dir/<shard file name>`, through a temporary file renamed into
    /// place, so that a merge never reads a half-written partial of a task still running.
    pub fn write(&self, dir: &Path) -> Result<PathBuf, ShardError> {
        std::fs::create_dir_all(dir).map_err(|e| ShardError::io(dir, e))?;
        let path = dir.join(self.shard.file_name());
        let tmp = dir.join(format!(".{}.tmp", self.shard.file_name()));
        let text = serde_json::to_string_pretty(self).map_err(ShardError::Encode)?;
        std::fs::write(&tmp, text + "\n").map_err(|e| ShardError::io(&tmp, e))?;
        std::fs::rename(&tmp, &path).map_err(|e| ShardError::io(&path, e))?;
        Ok(path)
    }

    /// Read one partial file.
    pub fn read(path: &Path) -> Result<Self, ShardError> {
        let text = std::fs::read_to_string(path).map_err(|e| ShardError::io(path, e))?;
        let p: Self = serde_json::from_str(&text).map_err(|source| ShardError::Parse {
            path: path.to_owned(),
            source,
        })?;
        if p.format != PARTIAL_FORMAT {
            return Err(ShardError::Format {
                path: path.to_owned(),
                found: p.format,
            });
        }
        Ok(p)
    }
}

/// Every partial under `inputs`: a directory gives its `*.partial.json` files (name order), a
/// file itself. Refused when one of them is empty of partials.
pub fn read_partials(inputs: &[PathBuf]) -> Result<Vec<(PathBuf, Partial)>, ShardError> {
    let mut out = Vec::new();
    for input in inputs {
        let mut files = Vec::new();
        if input.is_dir() {
            let rd = std::fs::read_dir(input).map_err(|e| ShardError::io(input, e))?;
            for entry in rd {
                let entry = entry.map_err(|e| ShardError::io(input, e))?;
                let name = entry.file_name();
                if name.to_string_lossy().ends_with(PARTIAL_SUFFIX)
                    && !name.to_string_lossy().starts_with('.')
                {
                    files.push(entry.path());
                }
            }
            files.sort();
            if files.is_empty() {
                return Err(ShardError::NoPartials(input.display().to_string()));
            }
        } else {
            files.push(input.clone());
        }
        for f in files {
            let p = Partial::read(&f)?;
            out.push((f, p));
        }
    }
    if out.is_empty() {
        return Err(ShardError::NoPartials("the inputs".into()));
    }
    Ok(out)
}

/// Check that `partials` are of one command, protocol and engine: the first partial's, whose
/// (command, protocol flags) are returned for the caller to rebuild the protocol from.
pub fn check_same_run(
    partials: &[(PathBuf, Partial)],
) -> Result<(String, serde_json::Value), ShardError> {
    let Some((first, p0)) = partials.first() else {
        return Err(ShardError::NoPartials("the inputs".into()));
    };
    for (path, p) in partials {
        if p.command != p0.command {
            return Err(ShardError::Command {
                path: path.clone(),
                found: p.command.clone(),
                first: first.clone(),
                expected: p0.command.clone(),
            });
        }
        if p.protocol_hash != p0.protocol_hash {
            return Err(ShardError::Protocol {
                path: path.clone(),
                found: p.protocol_hash.clone(),
                first: first.clone(),
                expected: p0.protocol_hash.clone(),
            });
        }
        if p.engine_hash != p0.engine_hash {
            return Err(ShardError::Engine {
                path: path.clone(),
                found: p.engine_hash.clone(),
                first: first.clone(),
                expected: p0.engine_hash.clone(),
            });
        }
    }
    Ok((p0.command.clone(), p0.protocol.clone()))
}

/// The merged results of a protocol: its closed-loop runs in plan order, each open-loop part's
/// runs in (N, seed) order, and the shards' stamp.
#[derive(Debug, Clone)]
pub struct Merged {
    /// Closed-loop runs, in [`StudyConfig::plan`] order.
    pub closed_loop: Vec<RunSummary>,
    /// Per open-loop part, its runs in (N, seed) order.
    pub open_loop: Vec<Vec<RunResult>>,
    /// Load averages of the shards and the slowest one's wall time.
    pub stamp: RunStamp,
    /// Every partial's file and shard, in the order given.
    pub shards: Vec<(PathBuf, Shard)>,
}

/// Merge `partials` (already of one run, [`check_same_run`]) over the protocol whose cells are
/// `cells`, closed-loop specs `plan` and open-loop parts `parts`: every cell exactly once, or an
/// error naming the cells missing (and the shards of which no partial came) and those doubled.
/// `protocol_hash` is what the partials' flags give in this build.
pub fn merge(
    cells: &[CellSpec],
    plan: &[RunSpec],
    parts: &[&OpenLoopConfig],
    protocol_hash: &str,
    partials: &[(PathBuf, Partial)],
) -> Result<Merged, ShardError> {
    let index: BTreeMap<&str, usize> = cells
        .iter()
        .enumerate()
        .map(|(k, c)| (c.id.as_str(), k))
        .collect();
    let mut holders: Vec<Vec<PathBuf>> = vec![Vec::new(); cells.len()];
    let mut closed: Vec<Option<RunSummary>> = vec![None; plan.len()];
    let mut open: BTreeMap<usize, OpenRecord> = BTreeMap::new();
    let mut shards_seen: BTreeMap<u32, Vec<u32>> = BTreeMap::new();
    for (path, p) in partials {
        if p.protocol_hash != protocol_hash {
            return Err(ShardError::ProtocolDrift {
                path: path.clone(),
                recorded: p.protocol_hash.clone(),
                here: protocol_hash.to_owned(),
            });
        }
        shards_seen
            .entry(p.shard.count)
            .or_default()
            .push(p.shard.index);
        let unknown = |cell: &str| ShardError::UnknownCell {
            path: path.clone(),
            cell: cell.to_owned(),
        };
        let shape = |cell: &str, what: String| ShardError::Shape {
            path: path.clone(),
            cell: cell.to_owned(),
            what,
        };
        for id in &p.cells {
            let k = *index.get(id.as_str()).ok_or_else(|| unknown(id))?;
            holders[k].push(path.clone());
        }
        for r in &p.closed_loop {
            let k = *index.get(r.cell.as_str()).ok_or_else(|| unknown(&r.cell))?;
            let CellKind::ClosedLoop(i) = cells[k].kind else {
                return Err(shape(
                    &r.cell,
                    "an open-loop cell recorded as a closed-loop run".into(),
                ));
            };
            let spec = plan
                .get(i)
                .cloned()
                .ok_or_else(|| shape(&r.cell, "not in the plan".into()))?;
            closed[i] = Some(r.summary(spec));
        }
        for r in &p.open_loop {
            let k = *index.get(r.cell.as_str()).ok_or_else(|| unknown(&r.cell))?;
            let CellKind::OpenLoop {
                part, condition, ..
            } = cells[k].kind
            else {
                return Err(shape(
                    &r.cell,
                    "a closed-loop run recorded as an open-loop cell".into(),
                ));
            };
            let cfg = parts.get(part).ok_or_else(|| {
                shape(
                    &r.cell,
                    format!("the protocol has no open-loop part {part}"),
                )
            })?;
            r.check(cfg, condition).map_err(|w| shape(&r.cell, w))?;
            open.insert(k, r.clone());
        }
        // A cell listed but without its record is as missing as one never run.
        for id in &p.cells {
            let k = index[id.as_str()];
            let recorded = match cells[k].kind {
                CellKind::ClosedLoop(i) => closed[i].is_some(),
                CellKind::OpenLoop { .. } => open.contains_key(&k),
            };
            if !recorded {
                return Err(shape(
                    id,
                    "listed among the shard's cells but not recorded".into(),
                ));
            }
        }
    }
    let missing: Vec<String> = holders
        .iter()
        .zip(cells)
        .filter(|(h, _)| h.is_empty())
        .map(|(_, c)| c.id.clone())
        .collect();
    let doubled: Vec<(String, Vec<PathBuf>)> = holders
        .iter()
        .zip(cells)
        .filter(|(h, _)| h.len() > 1)
        .map(|(h, c)| (c.id.clone(), h.clone()))
        .collect();
    if !missing.is_empty() || !doubled.is_empty() {
        let mut missing_shards = Vec::new();
        for (&count, seen) in &shards_seen {
            for i in 0..count {
                if !seen.contains(&i) {
                    missing_shards.push(format!("{i}/{count}"));
                }
            }
        }
        return Err(ShardError::Coverage {
            missing_shards,
            missing,
            total: cells.len(),
            doubled,
        });
    }
    let closed_loop = closed
        .into_iter()
        .zip(plan)
        .map(|(r, spec)| {
            r.ok_or_else(|| ShardError::Coverage {
                missing_shards: Vec::new(),
                missing: vec![spec.stem()],
                total: cells.len(),
                doubled: Vec::new(),
            })
        })
        .collect::<Result<Vec<_>, _>>()?;
    // Each part's (N, seed) results from its conditions' cells, in (N, seed) order.
    let mut open_loop: Vec<Vec<RunResult>> = parts.iter().map(|_| Vec::new()).collect();
    let mut runs: BTreeMap<(usize, usize), (u32, u64, Vec<&OpenRecord>)> = BTreeMap::new();
    for (&k, r) in &open {
        if let CellKind::OpenLoop { n, seed, part, .. } = cells[k].kind {
            // Cells are listed by (N, seed), then part and condition: the first cell of a run
            // orders it.
            let order = runs
                .iter()
                .find(|(_, (m, s, _))| *m == n && *s == seed)
                .map_or(k, |((o, _), _)| *o);
            runs.entry((order, part))
                .or_insert_with(|| (n, seed, Vec::new()))
                .2
                .push(r);
        }
    }
    for ((_, part), (n, seed, records)) in runs {
        if let (Some(out), Some(r)) = (open_loop.get_mut(part), assemble(n, seed, &records)) {
            out.push(r);
        }
    }
    let joined = |f: fn(&Partial) -> &str| {
        partials
            .iter()
            .map(|(_, p)| f(p))
            .collect::<Vec<_>>()
            .join(" / ")
    };
    let stamp = RunStamp {
        load_start: joined(|p| &p.load_start),
        load_end: joined(|p| &p.load_end),
        wall_s: partials.iter().map(|(_, p)| p.wall_s.0).fold(0.0, f64::max),
    };
    Ok(Merged {
        closed_loop,
        open_loop,
        stamp,
        shards: partials.iter().map(|(f, p)| (f.clone(), p.shard)).collect(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cell(id: &str, cost_s: f64) -> CellSpec {
        CellSpec {
            id: id.into(),
            cost_s,
            kind: CellKind::OpenLoop {
                n: 1,
                seed: 1,
                part: 0,
                condition: 0,
            },
            group: None,
            serial: false,
        }
    }

    #[test]
    fn shards_parse_and_refuse_with_the_limit() {
        assert_eq!(Shard::parse("2/3").ok(), Some(Shard { index: 2, count: 3 }));
        let e = Shard::parse("3/3").expect_err("out of range");
        assert!(e.to_string().contains("0 to 2 of 3"), "{e}");
        assert!(Shard::parse("1").is_err() && Shard::parse("a/2").is_err());
        assert!(matches!(Shard::parse("0/0"), Err(ShardError::ZeroCount)));
    }

    #[test]
    fn the_index_comes_from_kubernetes_or_slurm() {
        let env = |vars: &'static [(&'static str, &'static str)]| {
            move |k: &str| {
                vars.iter()
                    .find(|(n, _)| *n == k)
                    .map(|(_, v)| (*v).to_string())
            }
        };
        assert_eq!(Shard::from_env(None, env(&[])).ok(), Some(None));
        let k8s = env(&[("JOB_COMPLETION_INDEX", "5")]);
        assert_eq!(
            Shard::from_env(Some(8), k8s).ok().flatten(),
            Some(Shard { index: 5, count: 8 })
        );
        let e = Shard::from_env(None, env(&[("JOB_COMPLETION_INDEX", "5")])).expect_err("count");
        assert!(e.to_string().contains("--shards"), "{e}");
        // An array numbered from 1 is shard 0 at its first task; its size is the count.
        let slurm = env(&[
            ("SLURM_ARRAY_TASK_ID", "1"),
            ("SLURM_ARRAY_TASK_MIN", "1"),
            ("SLURM_ARRAY_TASK_COUNT", "4"),
        ]);
        assert_eq!(
            Shard::from_env(None, slurm).ok().flatten(),
            Some(Shard { index: 0, count: 4 })
        );
        let e = Shard::from_env(Some(4), env(&[("SLURM_ARRAY_TASK_ID", "x")])).expect_err("nan");
        assert!(e.to_string().contains("SLURM_ARRAY_TASK_ID"), "{e}");
        assert!(Shard::from_env(Some(4), env(&[])).is_err());
    }

    #[test]
    fn longest_cells_first_to_the_least_loaded_shard() {
        let cells = vec![
            cell("a", 1.0),
            cell("b", 10.0),
            cell("c", 4.0),
            cell("d", 4.0),
            cell("e", 3.0),
        ];
        // b -> 0; c -> 1; d -> 1 (4 < 10); e -> 0? loads 10, 8: e -> 1 (11); a -> 0 (11).
        assert_eq!(assign(&cells, 2), vec![0, 0, 1, 1, 1]);
        let b = Balance::of(&cells, 2);
        assert_eq!(b.loads, vec![11.0, 11.0]);
        assert!((b.slowest_share() - 0.5).abs() < 1e-12);
        // One shard takes everything; more shards than cells leave some empty.
        assert!(assign(&cells, 1).iter().all(|&s| s == 0));
        let b = Balance::of(&cells, 8);
        assert_eq!(b.slowest_s(), 10.0);
        assert_eq!(b.cells.iter().sum::<usize>(), 5);
    }

    #[test]
    fn a_group_is_split_only_where_that_shortens_the_slowest_shard() {
        let grouped = |id: &str, cost_s: f64| CellSpec {
            group: Some(CellGroup {
                key: "g".into(),
                cost_s: 6.0,
            }),
            ..cell(id, cost_s)
        };
        let with_alone = |alone: f64| {
            vec![
                grouped("g1", alone),
                grouped("g2", alone),
                grouped("g3", alone),
                cell("x", 5.0),
                cell("y", 1.0),
            ]
        };
        // Together the group's cells cost 6 on one thread; alone 3 each. Four two-thread shards:
        // whole, the group's shard takes 6 s; split, x's takes 5.
        let cells = with_alone(3.0);
        let owner = assign(&cells, 4);
        assert!(owner[0] != owner[1] || owner[1] != owner[2], "{owner:?}");
        let b = Balance::of(&cells, 4);
        assert_eq!(b.total_s, 15.0);
        assert_eq!(b.slowest_wall_s(WORKER_THREADS), 5.0);
        // Alone 10 each: splitting only adds work, so the group stays whole.
        let cells = with_alone(10.0);
        let owner = assign(&cells, 2);
        assert!(owner[0] == owner[1] && owner[1] == owner[2], "{owner:?}");
        assert_eq!(Balance::of(&cells, 2).total_s, 12.0);
        // One shard: nothing split.
        assert_eq!(Balance::of(&with_alone(3.0), 1).total_s, 12.0);
    }

    #[test]
    fn numbers_keep_their_bits_through_json() {
        let v = [
            0.1 + 0.2,
            1.0 / 3.0,
            f64::MIN_POSITIVE,
            5e-324,
            -0.0,
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            123_456_789.123_456_78,
        ];
        let text = serde_json::to_string(&nums(&v)).expect("encode");
        let back: Vec<Num> = serde_json::from_str(&text).expect("decode");
        for (a, b) in v.iter().zip(&back) {
            assert_eq!(a.to_bits(), b.0.to_bits(), "{a} in {text}");
        }
    }
}
