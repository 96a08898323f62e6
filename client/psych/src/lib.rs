//! # foveal-psych
//!
//! The paper's section 6 as numbers a scheduler can use: how well a viewer detects a collision
//! anomaly (two bodies repelling across a gap instead of touching) against the gap and its
//! eccentricity from the fixation, fitted to a viewer's own responses. foveal schedules and
//! measures with a perceptual function F(g, e) (section 3: F1 = g / e, F2 = g exp(-e / C), F3 =
//! F2 with C piecewise in e) whose constant the paper never gives; this crate fits it.
//!
//! The observer model: on a trial with on-screen gap `g` (degrees of visual angle, 0 when the
//! bodies touch) at eccentricity `e` (degrees), the viewer reports "apart" with probability
//!
//! ```text
//! p(g, e) = γ + (1 - γ - λ) W(F(g, e))      (g > 0)
//! p(0, e) = γ                               (touching: a false alarm)
//! W(x) = 1 - exp(-(x / α)^β)
//! ```
//!
//! with guess (false-alarm) rate γ, lapse rate λ, and a Weibull psychometric function of the
//! model's perceptual strength F, as psignifit and Palamedes parameterise a yes/no task. The
//! perceptual function carries the eccentricity: fitting it by maximum likelihood gives C (F2),
//! or C1..C3 (F3), with the psychometric function's threshold α and slope β.
//!
//! # Layout
//! - [`trial`]: one trial's record and the results CSV a PsychoPy or R user reads directly.
//! - [`model`]: the perceptual functions and the observer's response probability.
//! - [`fit`]: maximum-likelihood fits (Nelder-Mead, from `argmin`) with several starts.
//! - [`bootstrap`]: percentile intervals by refitting resampled trials.
//! - [`compare`]: cross-validated likelihood of competing functions.
//! - [`plot`]: the fit drawn (SVG): proportions with intervals and the fitted curves.
//! - [`report`]: fits of F1, F2 and F3 pooled and per participant, as markdown.
//! - [`simulate`]: simulated observers with a known function, for tests and coverage runs.
//! - [`rng`]: the deterministic generator the resampling and simulations draw from.
//!
//! ```
//! use foveal_psych::{fit::fit, model::{Function, Observer}, simulate::{simulate, Design}};
//! let truth = Observer { function: Function::F2 { c: 4.0 }, alpha: 0.05, beta: 2.0, guess: 0.05, lapse: 0.02 };
//! let trials = simulate(&truth, &Design::default(), 1);
//! let fitted = fit(&trials, Function::F2 { c: 1.0 }).expect("fits");
//! assert!(fitted.observer.function.constants()[0] > 2.0);
//! ```

pub mod bootstrap;
pub mod compare;
pub mod fit;
pub mod model;
pub mod plot;
pub mod report;
pub mod rng;
pub mod simulate;
pub mod trial;

pub use fit::{Fit, FitError, fit};
pub use model::{Function, Observer};
pub use trial::{Trial, TrialError};
