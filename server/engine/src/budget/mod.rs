//! The budget policy, in one place: what a frame may spend and how it decides what to shed.
//!
//! - [`meter`]: the [`FrameBudget`] and the narrow phase's [`Meter`] (paper section
//!   2: "the application indicates that it wishes to interrupt collision processing").
//! - [`plan`]: one frame's plan under its budget: the deadline less the learnt hand-back and guard
//!   band, the narrow phase's own deadline, the metrics' effort, and what the frame learns at its
//!   end (`FramePolicy`).
//! - [`guard`]: the guard band a wall-clock budget keeps against the machine's stalls.
//! - [`shedding`]: what a whole-frame wall-clock budget sheds at large N, in perceptual order.
//! - [`gate`]: whether a wall-clock frame can pay for its optional work (the ordering, the gaze
//!   rings), learnt from the frames that did it.

pub mod gate;
pub mod guard;
pub mod meter;
pub mod plan;
pub mod shedding;

pub use crate::clock::{Clock, FrozenClock};
#[cfg(test)]
pub(crate) use crate::clock::{Manual, Ticking};
pub use gate::{CostGate, ExactGate, LEARN_FRAMES};
pub use meter::{FrameBudget, Meter};
pub(crate) use plan::{FramePlan, FramePolicy};
