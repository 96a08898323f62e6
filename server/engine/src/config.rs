//! Configuration of a simulation and its validation.
//!
//! Defaults are the canonical "paper scene" of DESIGN.md (section 4 of the paper): density 10 bodies
//! per unit volume, shape radius R = 0.2, depth-4 sphere trees, dt = 1/60 s. Every field is checked
//! by [`SimConfig::validate`], which names the field and the allowed range in its error.

use serde::{Deserialize, Serialize};

use crate::perception::{CameraConfig, Display, PerceptualModel};
pub use crate::validate::ConfigError;
use crate::validate::{check_finite_positive, check_finite_range};

/// Largest body count the engine accepts. Memory is about 200 bytes per body plus the pair lists;
/// 2,000,000 bodies is roughly 1 GiB at the paper's density, the most a frame can touch usefully.
pub const MAX_BODIES: u32 = 2_000_000;
/// Deepest sphere tree: a depth-7 tree of this shape has ~14,000 leaves and its octree cells are
/// smaller than f32 resolves relative to R at extreme scales.
pub const MAX_DEPTH: usize = 6;
/// Far-from-origin limit on the volume's corner (scene units). World state is f64 and every narrow
/// phase test is done relative to the pair, so precision is lost only in `position + velocity * dt`:
/// at 1e9 one f64 ulp is ~1e-7, which is still below a thousandth of a step at the slowest speed
/// of the default scene. Beyond that, integration itself degrades, so configs are refused.
pub const MAX_ORIGIN: f64 = 1e9;

/// Most worker threads a simulation may use.
pub const MAX_THREADS: u32 = 64;

/// The scene: how many bodies, where, how fast (DESIGN.md "Scene").
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct SceneConfig {
    /// Number of bodies, 1..=2,000,000.
    pub bodies: u32,
    /// Seed of the scene generator.
    pub seed: u64,
    /// Bodies per unit volume; the cube side is (N / density)^(1/3).
    pub density: f64,
    /// Bounding radius R of the star shape (scene units).
    pub shape_radius: f64,
    /// Sphere-tree depth, 1..=6 (paper: 4).
    pub depth: u32,
    /// Time step (seconds).
    pub dt: f64,
    /// Speed range (units/s), uniform.
    pub min_speed: f64,
    /// Upper end of the speed range (units/s).
    pub max_speed: f64,
    /// Angular speed is uniform in [0, max_spin] rad/s about a random axis.
    pub max_spin: f64,
    /// World position of the volume's minimum corner (scene units).
    pub origin: [f64; 3],
    /// What "colliding" means: the drawn stars touch (default), or the paper's leaf spheres
    /// overlap (docs/DESIGN.md "Exact answer"). A serialised config without this field was
    /// written before it existed, under the leaf truth, and is read as such: a session recorded
    /// then replays as it ran.
    #[serde(default = "Truth::before_it_was_recorded")]
    pub truth: Truth,
    /// How the sphere tree groups the leaves (docs/DESIGN.md "Sphere tree"). The leaves, and so
    /// every exact answer, are the same under each; what differs is how many sphere tests a pair
    /// takes to settle. A serialised config without this field was written before it existed,
    /// with the paper's octree, and is read as such.
    #[serde(default = "TreeKind::before_it_was_recorded")]
    pub tree: TreeKind,
}

/// The sphere tree's hierarchy over one and the same set of leaves (docs/DESIGN.md "Sphere
/// tree"): the paper's octree cells, the same cells with every inner sphere fitted to the leaves
/// below it, or fitted spheres over the star's parts.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum TreeKind {
    /// The paper's octree (section 2): each inner sphere circumscribes its grid cell, so it
    /// reaches past the leaves below it (a level-2 sphere reaches 1.73R from the centre, the
    /// root 1.11R). For the replication.
    Octree,
    /// The octree's cells, each inner sphere the smallest found that holds the leaves below it.
    Fitted,
    /// Level 2 grouped by the star's parts (the core and the six spikes), each part's leaves
    /// under it by their octree cells, every inner sphere fitted: a pair of spikes far from each
    /// other is told apart at level 2 instead of after a descent into both octants.
    #[default]
    Parts,
}

impl TreeKind {
    /// Every kind, the default first.
    pub const ALL: [TreeKind; 3] = [Self::Parts, Self::Fitted, Self::Octree];

    /// Stable short name (`--tree` flags, CSV columns, reports).
    pub fn name(self) -> &'static str {
        match self {
            Self::Octree => "octree",
            Self::Fitted => "fitted",
            Self::Parts => "parts",
        }
    }

    /// Parse a [`Self::name`].
    pub fn from_name(s: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|t| t.name() == s)
    }

    /// The tree of a serialised config that does not name one: the paper's octree, the only
    /// one before the kind was recorded.
    pub fn before_it_was_recorded() -> Self {
        Self::Octree
    }
}

impl std::fmt::Display for TreeKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

impl std::str::FromStr for TreeKind {
    type Err = ConfigError;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Self::from_name(s).ok_or_else(|| {
            ConfigError::new("scene.tree", s, "must be `parts`, `fitted` or `octree`")
        })
    }
}

/// The definition of the exact answer a frame is measured against (docs/DESIGN.md "Exact answer").
///
/// The paper decides a collision on the leaf spheres of the sphere tree (section 2). Those spheres
/// contain the star but overshoot it by up to 0.36R next to the spike tips, so under that truth
/// bodies bounce across a visible gap. Under [`Truth::Shape`] a pair whose leaves overlap is then
/// tested on the star itself (core ball and six cones), and "colliding" means the drawn shapes
/// touch. The leaf truth stays for the paper's replication and its golden hash.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Truth {
    /// Two bodies collide iff their stars (core ball plus six cones) touch.
    #[default]
    Shape,
    /// Two bodies collide iff a leaf sphere of one overlaps a leaf sphere of the other (the paper).
    LeafSpheres,
}

impl Truth {
    /// Both truths, the default first.
    pub const ALL: [Truth; 2] = [Self::Shape, Self::LeafSpheres];

    /// Stable short name (`--truth` flags, CSV columns, reports).
    pub fn name(self) -> &'static str {
        match self {
            Self::Shape => "shape",
            Self::LeafSpheres => "leaf-spheres",
        }
    }

    /// Parse a [`Self::name`].
    pub fn from_name(s: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|t| t.name() == s)
    }

    /// The truth of a serialised config that does not name one: every config written before
    /// the truth was recorded ran under the leaf spheres.
    pub fn before_it_was_recorded() -> Self {
        Self::LeafSpheres
    }
}

impl std::fmt::Display for Truth {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

impl std::str::FromStr for Truth {
    type Err = ConfigError;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Self::from_name(s)
            .ok_or_else(|| ConfigError::new("scene.truth", s, "must be `shape` or `leaf-spheres`"))
    }
}

impl Default for SceneConfig {
    fn default() -> Self {
        Self {
            bodies: 500,
            seed: 1,
            density: 10.0,
            shape_radius: 0.2,
            depth: 4,
            dt: 1.0 / 60.0,
            min_speed: 0.2,
            max_speed: 1.0,
            max_spin: std::f64::consts::PI,
            origin: [0.0; 3],
            truth: Truth::Shape,
            tree: TreeKind::Parts,
        }
    }
}

impl SceneConfig {
    /// The paper scene with `bodies` bodies and `seed`, everything else default.
    pub fn paper(bodies: u32, seed: u64) -> Self {
        Self {
            bodies,
            seed,
            ..Self::default()
        }
    }

    /// Side of the cubic volume: density is held constant as N grows (paper section 4).
    pub fn volume_side(&self) -> f64 {
        (f64::from(self.bodies) / self.density).cbrt()
    }

    /// Check every field; the error names the first offending one.
    pub fn validate(&self) -> Result<(), ConfigError> {
        if self.bodies == 0 || self.bodies > MAX_BODIES {
            return Err(ConfigError::new(
                "scene.bodies",
                self.bodies,
                format!("must be in 1..={MAX_BODIES}"),
            ));
        }
        check_finite_positive("scene.density", self.density)?;
        check_finite_range("scene.shape_radius", self.shape_radius, 1e-6, 1e6)?;
        if !(1..=MAX_DEPTH as u32).contains(&self.depth) {
            return Err(ConfigError::new(
                "scene.depth",
                self.depth,
                format!("must be in 1..={MAX_DEPTH}"),
            ));
        }
        check_finite_range("scene.dt", self.dt, 1e-7, 10.0)?;
        check_finite_range("scene.min_speed", self.min_speed, 0.0, 1e12)?;
        check_finite_range("scene.max_speed", self.max_speed, self.min_speed, 1e12)?;
        check_finite_range("scene.max_spin", self.max_spin, 0.0, 1e6)?;
        for (field, v) in ["scene.origin.x", "scene.origin.y", "scene.origin.z"]
            .into_iter()
            .zip(self.origin)
        {
            check_finite_range(field, v, -MAX_ORIGIN, MAX_ORIGIN)?;
        }
        let side = self.volume_side();
        if !side.is_finite() || side <= 0.0 {
            return Err(ConfigError::new(
                "scene.density",
                self.density,
                "gives a non-finite volume side",
            ));
        }
        Ok(())
    }
}

/// When the narrow phase stops (paper section 2, "interruptible").
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum BudgetSpec {
    /// Never interrupt: every candidate pair is resolved exactly.
    #[default]
    Exact,
    /// Interrupt before the first sphere test: every candidate pair is deemed colliding.
    InterruptAtZero,
    /// Wall-clock budget for the whole frame (integration to metrics; the audit, when on, runs
    /// after it), in milliseconds, measured by the caller's clock.
    WallMs(f64),
    /// Deterministic budget: at most this many sphere tests per frame.
    SphereTests(u64),
    /// A fraction of the exact narrow phase's cost (sphere tests per frame, calibrated on this scene),
    /// so a study transfers between machines of very different speed.
    FractionOfExact(f64),
}

impl BudgetSpec {
    /// Check the budget's parameter.
    pub fn validate(&self) -> Result<(), ConfigError> {
        match *self {
            Self::Exact | Self::InterruptAtZero | Self::SphereTests(_) => Ok(()),
            Self::WallMs(ms) => check_finite_range("budget.wall_ms", ms, 0.0, 60_000.0),
            Self::FractionOfExact(f) => check_finite_range("budget.fraction_of_exact", f, 0.0, 1.0),
        }
    }
}

/// Which scheduler orders the narrow-phase work (paper sections 2 and 4; `ExpectedGain` is ours).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SchedulerKind {
    /// Every active pair descends one level per round, in list order.
    RoundRobin,
    /// Each pair is resolved completely before the next, in list order.
    Sequential,
    /// Pairs sorted by perceptual priority, then resolved sequentially.
    SortedSequential,
    /// Two queues split by an eccentricity threshold; round-robin inside each, inner queue first.
    PriorityOnly,
    /// Inner queue sorted and sequential, outer queue round-robin.
    PrioritySorted,
    /// Ours: greedy on expected perceived error removed per sphere test.
    ExpectedGain,
    /// Ours: each step priced by the false-positive perceived error it is expected to remove per
    /// sphere test, with probabilities and costs calibrated on exact runs of the paper scene.
    Priced,
}

impl SchedulerKind {
    /// Every scheduler, in the order tables list them.
    pub const ALL: [SchedulerKind; 7] = [
        Self::RoundRobin,
        Self::Sequential,
        Self::SortedSequential,
        Self::PriorityOnly,
        Self::PrioritySorted,
        Self::ExpectedGain,
        Self::Priced,
    ];

    /// Stable short name (CLI flags, CSV columns).
    pub fn name(self) -> &'static str {
        match self {
            Self::RoundRobin => "round-robin",
            Self::Sequential => "sequential",
            Self::SortedSequential => "sorted-sequential",
            Self::PriorityOnly => "priority-only",
            Self::PrioritySorted => "priority-sorted",
            Self::ExpectedGain => "expected-gain",
            Self::Priced => "priced",
        }
    }

    /// Parse a [`Self::name`].
    pub fn from_name(s: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|k| k.name() == s)
    }

    /// Whether the scheduler needs a perceptual priority per pair (and so a fixation).
    pub fn needs_priority(self) -> bool {
        !matches!(self, Self::RoundRobin | Self::Sequential)
    }
}

/// Ablation switches of the priced scheduler ([`crate::schedule::Priced`]): which parts of the
/// price are used.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(default)]
pub struct PricedOptions {
    /// Weigh by the calibrated expected false-positive gap (off: every pair is assumed a false
    /// positive with the same gap).
    pub probability: bool,
    /// Divide by the calibrated expected tests to settle (off: every pair costs the same).
    pub cost: bool,
    /// Weigh by the perceptual fall-off around the fixation (off: gaze-blind).
    pub gaze: bool,
}

impl Default for PricedOptions {
    fn default() -> Self {
        Self {
            probability: true,
            cost: true,
            gaze: true,
        }
    }
}

impl PricedOptions {
    /// Short label for tables: `priced`, or `priced-no-probability` and so on.
    pub fn label(&self) -> String {
        let mut s = String::from("priced");
        for (on, name) in [
            (self.probability, "probability"),
            (self.cost, "cost"),
            (self.gaze, "gaze"),
        ] {
            if !on {
                s.push_str("-no-");
                s.push_str(name);
            }
        }
        s
    }
}

/// Everything a [`crate::Simulation`] is built from.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct SimConfig {
    /// The scene.
    pub scene: SceneConfig,
    /// Narrow-phase budget.
    pub budget: BudgetSpec,
    /// Scheduler.
    pub scheduler: SchedulerKind,
    /// Priority-queue threshold: pairs whose centre of collision is within this eccentricity
    /// (degrees of visual angle) of the fixation go to the first queue.
    pub eccentricity_threshold_deg: f64,
    /// Model used to prioritise collisions. The default is F2 averaged over C in [1, 10] degrees
    /// ([`PerceptualModel::scheduling_default`]): measured open loop, scheduling with it is never
    /// worse than round-robin whichever of C = 1, 2 or 5 degrees the viewer really has, where
    /// scheduling with C = 1 is up to 1.7x worse than round-robin for a C = 5 viewer.
    pub schedule_model: PerceptualModel,
    /// Model used to measure perceived inaccuracy P.
    pub measure_model: PerceptualModel,
    /// Compute the exact answer for every deemed pair (true false positives, true Δ and P).
    pub audit: bool,
    /// Display geometry (for pixels and degrees of visual angle).
    pub display: Display,
    /// Camera placement.
    pub camera: CameraConfig,
    /// Frames run in exact mode on a private copy of the scene to calibrate
    /// [`BudgetSpec::FractionOfExact`].
    pub calibration_frames: u32,
    /// Frames the calibration copy runs first, uncounted: random placement starts the scene with
    /// deep overlaps that cost 2-4x the steady state for about a second of simulated time.
    pub calibration_warmup: u32,
    /// Broad-phase algorithm (`auto` picks by the number of bodies).
    pub broad_phase: crate::broad_phase::BroadPhaseKind,
    /// Ablation switches of the priced scheduler (all on by default).
    pub priced: PricedOptions,
    /// Worker threads the frame's phases may use (1..=64). Results do not depend on it: under a
    /// sphere-test budget frame reports are bit-identical for every thread count.
    pub threads: u32,
    /// Renumber the bodies in the grid's cell order at creation and then every this many frames
    /// (0: never), so that bodies near in space stay near in memory as they move. Only where the
    /// broad phase is the grid (large N); under a wall-clock budget only at creation (a
    /// renumbering costs about 0.1 us per body). Body ids seen from outside
    /// ([`crate::Simulation::body_ids`]) never change.
    pub renumber_every: u32,
    /// Under a wall-clock budget with a fixation, settle every pair within 5 degrees of it
    /// ([`crate::report::FOVEAL_DEG`]) before anything else, at every N (priced scheduler).
    ///
    /// What the viewer looks at is then exact: the priced order alone leaves the fovea's pairs
    /// that will likely collide for last (deeming a true collision costs no perceived error P),
    /// and a deemed pair's response comes from an interrupted traversal, not the exact contact.
    /// The price is P elsewhere: the foveal pairs' descents come out of the same budget
    /// (docs/BENCHMARKS.md measures both). Without it the priced scheduler already settles them
    /// first where sweep and prune's columns let the gaze rings find them and the frame can pay
    /// for placing the rings (`schedule::rings`); this pass needs neither, and runs before the
    /// root pass. At large N the broad phase's regions already put the foveal pairs first
    /// whatever this says; sphere-test budgets and exact frames never take the pass.
    pub fovea_first: bool,
    /// Under a wall-clock budget, a frame expected to afford the exact narrow phase takes it
    /// (see `budget::gate::ExactGate`), so that a budget never makes a frame slower or worse
    /// than exact. Off where schedulers are compared under the same budgets on identical
    /// frames (the open loop: a probe would spend one frame's budget on a pass it cannot
    /// finish), and in tests of the ordered path.
    pub exact_when_affordable: bool,
}

impl Default for SimConfig {
    fn default() -> Self {
        Self {
            scene: SceneConfig::default(),
            budget: BudgetSpec::Exact,
            scheduler: SchedulerKind::Priced,
            eccentricity_threshold_deg: 5.0,
            schedule_model: PerceptualModel::scheduling_default(),
            measure_model: PerceptualModel::default(),
            audit: false,
            display: Display::default(),
            camera: CameraConfig::default(),
            calibration_frames: 30,
            calibration_warmup: 60,
            threads: 1,
            broad_phase: crate::broad_phase::BroadPhaseKind::Auto,
            priced: PricedOptions::default(),
            renumber_every: DEFAULT_RENUMBER_EVERY,
            fovea_first: false,
            exact_when_affordable: true,
        }
    }
}

/// Frames between two renumberings by default: bodies cross about a tenth of a grid cell per
/// frame in the paper scene, so after two seconds at 60 Hz most are still within a cell or two
/// of their place in memory, and the renumbering's cost (a gather of every per-body array) is
/// spread over 120 frames.
pub const DEFAULT_RENUMBER_EVERY: u32 = 120;

impl SimConfig {
    /// Check every field; the error names the first offending one.
    pub fn validate(&self) -> Result<(), ConfigError> {
        self.scene.validate()?;
        self.budget.validate()?;
        check_finite_range(
            "eccentricity_threshold_deg",
            self.eccentricity_threshold_deg,
            0.0,
            180.0,
        )?;
        self.schedule_model.validate("schedule_model")?;
        self.measure_model.validate("measure_model")?;
        self.display.validate()?;
        self.camera.validate()?;
        if self.calibration_warmup > 100_000 {
            return Err(ConfigError::new(
                "calibration_warmup",
                self.calibration_warmup,
                "must be <= 100000",
            ));
        }
        if !(1..=MAX_THREADS).contains(&self.threads) {
            return Err(ConfigError::new(
                "threads",
                self.threads,
                format!("must be in 1..={MAX_THREADS}"),
            ));
        }
        if matches!(self.budget, BudgetSpec::FractionOfExact(_)) && self.calibration_frames == 0 {
            return Err(ConfigError::new(
                "calibration_frames",
                0,
                "must be >= 1 with budget fraction_of_exact",
            ));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_are_valid_and_errors_name_the_field() {
        SimConfig::default().validate().expect("defaults valid");
        let mut c = SimConfig::default();
        c.scene.bodies = 0;
        assert_eq!(c.validate().map_err(|e| e.field), Err("scene.bodies"));
        c.scene.bodies = MAX_BODIES + 1;
        let e = c.validate().expect_err("too many");
        assert!(e.to_string().contains("2000000"), "{e}");
        let mut c = SimConfig::default();
        c.scene.shape_radius = f64::NAN;
        assert_eq!(c.validate().map_err(|e| e.field), Err("scene.shape_radius"));
        let mut c = SimConfig::default();
        c.scene.dt = -1.0;
        assert_eq!(c.validate().map_err(|e| e.field), Err("scene.dt"));
        let mut c = SimConfig::default();
        c.scene.depth = 7;
        assert_eq!(c.validate().map_err(|e| e.field), Err("scene.depth"));
        let mut c = SimConfig::default();
        c.budget = BudgetSpec::WallMs(-1.0);
        assert_eq!(c.validate().map_err(|e| e.field), Err("budget.wall_ms"));
        let mut c = SimConfig::default();
        c.scene.origin[1] = 1e12;
        assert_eq!(c.validate().map_err(|e| e.field), Err("scene.origin.y"));
    }

    /// A config serialised before the truth existed replays under the leaf truth it ran
    /// under; one that names its truth keeps it; the programmatic default is the shape.
    #[test]
    fn a_config_without_a_truth_is_read_as_the_leaf_truth() {
        let mut json = serde_json::to_value(SceneConfig::default()).expect("serialises");
        assert_eq!(json["truth"], "shape");
        let named: SceneConfig = serde_json::from_value(json.clone()).expect("parses");
        assert_eq!(named.truth, Truth::Shape);
        json.as_object_mut().expect("object").remove("truth");
        let old: SceneConfig = serde_json::from_value(json).expect("parses");
        assert_eq!(old.truth, Truth::LeafSpheres);
        assert_eq!(SceneConfig::default().truth, Truth::Shape);
    }

    #[test]
    fn scheduler_names_round_trip() {
        for k in SchedulerKind::ALL {
            assert_eq!(SchedulerKind::from_name(k.name()), Some(k));
        }
        assert_eq!(SchedulerKind::from_name("nope"), None);
    }
}
