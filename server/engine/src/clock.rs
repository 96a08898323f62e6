//! Time enters the engine only here: through a [`Clock`] the caller hands in. The engine never
//! reads a wall clock itself, so that it stays pure and a run under a sphere-test budget with a
//! [`FrozenClock`] replays bit for bit on any machine.

/// A monotonic clock supplied by the caller. It is `Sync` because a frame on several threads runs
/// on the simulation's thread pool, which reads it from there.
pub trait Clock: Sync {
    /// Nanoseconds since an arbitrary fixed origin; never decreases.
    fn now_ns(&self) -> u64;
}

/// A clock that never advances: for deterministic runs where time is not measured.
#[derive(Debug, Clone, Copy, Default)]
pub struct FrozenClock;

impl Clock for FrozenClock {
    fn now_ns(&self) -> u64 {
        0
    }
}

/// A clock for tests that advances `.1` nanoseconds at every reading (`.0` holds the last one),
/// so a frame's timing depends only on how often it reads the clock.
#[cfg(test)]
pub(crate) struct Ticking(pub std::sync::atomic::AtomicU64, pub u64);

#[cfg(test)]
impl Clock for Ticking {
    fn now_ns(&self) -> u64 {
        self.0
            .fetch_add(self.1, std::sync::atomic::Ordering::Relaxed)
            + self.1
    }
}

/// A clock for tests that reads whatever `.0` was last set to.
#[cfg(test)]
pub(crate) struct Manual(pub std::sync::atomic::AtomicU64);

#[cfg(test)]
impl Clock for Manual {
    fn now_ns(&self) -> u64 {
        self.0.load(std::sync::atomic::Ordering::Relaxed)
    }
}
