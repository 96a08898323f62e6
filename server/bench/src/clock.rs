//! The wall clock the bench hands the engine (the engine reads time only through a
//! [`Clock`] it is given).

use std::time::Instant;

use foveal_engine::Clock;

/// A monotonic wall clock for the engine: nanoseconds since the clock was made.
#[derive(Debug, Clone, Copy)]
pub struct InstantClock(Instant);

impl InstantClock {
    /// A clock starting now.
    pub fn new() -> Self {
        Self(Instant::now())
    }
}

impl Default for InstantClock {
    fn default() -> Self {
        Self::new()
    }
}

impl Clock for InstantClock {
    fn now_ns(&self) -> u64 {
        self.0.elapsed().as_nanos() as u64
    }
}
