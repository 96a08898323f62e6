//! The stress soak (robustness suite): long runs checked frame by frame with
//! [`foveal_engine::soak`], at the sizes the stress issue names, plus the same scene far from the
//! origin. Each case reports every invariant's worst value and whether it held.

use std::fmt::Write as _;
use std::time::Instant;

use foveal_engine::SimConfig;
use foveal_engine::soak::{SoakLimits, SoakReport, soak};

use crate::runner::progress_bar;

/// One soak case.
#[derive(Debug, Clone)]
pub struct StressCase {
    /// Short label for tables.
    pub name: String,
    /// Scene and models (the soak forces the exact budget).
    pub config: SimConfig,
    /// Frames to run.
    pub frames: u64,
}

/// A finished case.
#[derive(Debug, Clone)]
pub struct StressResult {
    /// The case.
    pub case: StressCase,
    /// What the soak found.
    pub report: SoakReport,
    /// Whether every invariant held.
    pub passed: bool,
    /// Wall time, seconds.
    pub wall_s: f64,
}

fn case(name: &str, bodies: u32, frames: u64, origin: f64) -> StressCase {
    let mut config = SimConfig::default();
    config.scene.bodies = bodies;
    config.scene.seed = 1;
    config.scene.origin = [origin; 3];
    StressCase {
        name: name.to_string(),
        config,
        frames,
    }
}

/// The soak: 1,000,000 frames at N = 100 and 20,000 at N = 10,000, and 20,000 frames at
/// N = 1,000 translated by 1e7 units. `quick` divides every frame count by 100.
pub fn default_cases(quick: bool) -> Vec<StressCase> {
    let k = if quick { 100 } else { 1 };
    vec![
        case("N=100", 100, 1_000_000 / k, 0.0),
        case("N=10000", 10_000, 20_000 / k, 0.0),
        case("N=1000 at 1e7", 1_000, 20_000 / k, 1e7),
    ]
}

/// Run `cases` one after another with a progress bar per case.
pub fn run(
    cases: Vec<StressCase>,
    limits: SoakLimits,
    progress: bool,
) -> Result<Vec<StressResult>, foveal_engine::ConfigError> {
    let mut out = Vec::new();
    for case in cases {
        let pb = progress_bar(case.frames, progress);
        pb.set_message(case.name.clone());
        let started = Instant::now();
        let report = soak(&case.config, case.frames, limits, |done| {
            pb.set_position(done)
        })?;
        pb.finish_and_clear();
        let passed = report.passed(&limits, case.config.scene.volume_side());
        out.push(StressResult {
            wall_s: started.elapsed().as_secs_f64(),
            case,
            report,
            passed,
        });
    }
    Ok(out)
}

/// The results as a markdown table (one row per case).
pub fn markdown(results: &[StressResult], limits: &SoakLimits) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "Limits: bodies inside the volume within {:e} of its side; | |q| - 1 | <= {:e}; momentum (net of wall impulses) and kinetic energy drift <= 1e-9 relative; no pair colliding for more than {} consecutive frames without moving apart while only the two of them touch (two-body sticking); no tunnelling. Long contacts pushed together by a third body or a wall are counted, not failed.\n",
        limits.outside_fraction, limits.quat_tolerance, limits.stuck_frames
    );
    let _ = writeln!(
        s,
        "| case | frames | wall s | non-finite frames | max outside | max quat error | momentum drift | energy drift | longest contact (frames) | long contacts (3rd body/wall) | stuck | tunnelled | collisions | result |"
    );
    let _ = writeln!(
        s,
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
    );
    for r in results {
        let p = &r.report;
        let _ = writeln!(
            s,
            "| {} | {} | {:.0} | {} | {:.1e} | {:.1e} | {:.1e} | {:.1e} | {} | {} | {} | {} | {} | {} |",
            r.case.name,
            p.frames,
            r.wall_s,
            p.non_finite_frames,
            p.max_outside,
            p.max_quat_error,
            p.max_momentum_drift,
            p.max_energy_drift,
            p.longest_overlap,
            p.long_contacts,
            p.stuck_pairs,
            p.tunnelled,
            p.collisions,
            if r.passed { "pass" } else { "FAIL" }
        );
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_short_soak_passes_and_renders() {
        let cases = vec![case("tiny", 50, 200, 0.0), case("tiny far", 50, 200, 1e5)];
        let limits = SoakLimits::default();
        let results = run(cases, limits, false).expect("valid");
        assert!(results.iter().all(|r| r.passed), "{results:?}");
        let md = markdown(&results, &limits);
        assert_eq!(md.lines().filter(|l| l.starts_with("| tiny")).count(), 2);
        assert!(md.contains("| pass |"));
    }
}
