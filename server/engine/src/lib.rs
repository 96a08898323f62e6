//! # foveal-engine
//!
//! The simulation of O'Sullivan, "A Model of Collision Perception for Real-Time Animation": many
//! identical star-shaped rigid bodies in a box, a sweep-and-prune broad phase, an interruptible
//! sphere-tree narrow phase under a per-frame budget, and perceptual scheduling of the narrow phase
//! around the viewer's fixation. Pure, synchronous and deterministic: no I/O, no clock but the
//! [`Clock`] the caller hands to [`Simulation::step`], and threads only inside a step (a frame on
//! several threads runs on the simulation's own rayon pool and returns when its work is done; no
//! output depends on the thread count).
//!
//! # Layout
//! The modules a user of the library needs are public; the rest are the crate's own, and what a
//! user needs of them ([`Simulation`], the configs, [`Viewer`], [`Clock`]) is re-exported here.
//! - `config`: scene, budget, scheduler and model configuration, validated with errors that name
//!   the field and the range.
//! - `validate`: the field-naming [`ConfigError`] and range checks every config type uses.
//! - [`shape`], [`sphere_tree`]: the star shape and its flat, level-ordered octree sphere tree.
//! - [`world`]: body state and integration (walls reflect).
//! - [`broad_phase`]: sweep and prune with temporal coherence at the paper's N, a uniform grid
//!   beyond; chosen by the scene.
//! - [`narrow_phase`]: per-pair traversal state, one level of one tree per step (pair state,
//!   traversal, kernels, witnesses and exact separation, a file each).
//! - `clock`: the [`Clock`] through which alone time enters the engine.
//! - [`budget`]: the budget policy: wall-clock and sphere-test budgets, the
//!   narrow phase's meter, each frame's plan, the guard band, shedding and the cost gates.
//! - [`schedule`]: round-robin, sequential, sorted, priority-queue, expected-gain and priced
//!   schedulers, each declaring the passes it wants of a frame.
//! - [`calibrate`]: start-up calibration of the priced scheduler's prices on exact runs of whole
//!   simulations (above the schedulers, whose table it fills).
//! - `perception`, [`fixation`]: camera, display, visual angle, F1/F2/F3.
//! - `falloff`: the models' eccentricity fall-off tabulated for per-pair lookup without libm.
//! - `response`: velocity exchange.
//! - [`metrics`]: Δ, P and counts of a frame, exact or sampled with a stated error.
//! - [`report`]: the frame record, the phase profile and the audit.
//! - [`collider`]: prioritise, narrow phase, metrics and audit on frames handed in (closed and
//!   open loop); [`clairvoyant`]: the least true P any schedule could reach with a budget.
//! - `simulation`: one frame of the main loop as named, timed stages; `export`: a frame as JSON.
//! - [`soak`]: long-run invariant checks for the stress suite.
//!
//! ```
//! use foveal_engine::{FrozenClock, Fixation, SimConfig, Simulation};
//! let mut cfg = SimConfig::default();
//! cfg.scene.bodies = 100;
//! let mut sim = Simulation::new(cfg).expect("valid config");
//! let report = sim.step(Some(Fixation::at(0.5, 0.5)), &FrozenClock);
//! assert_eq!(report.deemed, 0); // the default budget is exact
//! ```

// Tests build configs by mutating defaults and index parallel arrays; both read better as is.
#![cfg_attr(
    test,
    allow(clippy::field_reassign_with_default, clippy::needless_range_loop)
)]

pub mod broad_phase;
pub mod budget;
pub mod calibrate;
pub mod clairvoyant;
pub(crate) mod clock;
pub mod collider;
pub(crate) mod config;
pub(crate) mod export;
pub(crate) mod falloff;
pub mod fixation;
pub mod math;
pub mod metrics;
pub mod narrow_phase;
pub mod near_memo;
pub(crate) mod perception;
pub(crate) mod prefetch;
pub mod report;
pub(crate) mod response;
pub(crate) mod rng;
pub mod schedule;
pub mod shape;
pub(crate) mod simd;
pub(crate) mod simulation;
pub mod soak;
pub mod sphere_tree;
pub mod star_contact;
pub(crate) mod validate;
pub mod warm;
pub mod world;

pub use budget::FrameBudget;
pub use clock::{Clock, FrozenClock};
pub use config::{
    BudgetSpec, ConfigError, DEFAULT_RENUMBER_EVERY, MAX_BODIES, MAX_DEPTH, MAX_ORIGIN,
    MAX_THREADS, PricedOptions, SceneConfig, SchedulerKind, SimConfig, TreeKind, Truth,
};
pub use fixation::Fixation;
pub use perception::{
    CameraConfig, Display, EccentricityUnit, PerceptualFunction, PerceptualModel, Viewer,
};
pub use report::{AuditReport, DeemedTruth, FrameReport, PassCost, PassCosts, PhaseProfile};
pub use simulation::{MAX_POOL_WARM_NS, Simulation};
