//! Asking the memory for data a loop will read soon, where the processor's own prefetchers cannot
//! guess it: reads by index (a body's state by id) that follow no stride.
//!
//! Only a hint: the address is computed, never dereferenced, so an index past the end is harmless
//! and nothing here needs `unsafe`. Where the processor offers no prefetch instruction (or is not
//! x86-64) the hint does nothing and the loop runs as it would without it.

/// A prefetch hint, detected once and kept for a loop.
#[derive(Debug, Clone, Copy)]
pub struct Prefetcher {
    #[cfg(target_arch = "x86_64")]
    sse: Option<pulp::x86::V1>,
}

impl Prefetcher {
    /// What this processor offers.
    #[inline]
    pub fn new() -> Self {
        Self {
            #[cfg(target_arch = "x86_64")]
            sse: pulp::x86::V1::try_new(),
        }
    }

    /// Ask for the cache line holding `items[i]` into every cache level.
    #[inline(always)]
    pub fn hint<T>(&self, items: &[T], i: usize) {
        #[cfg(target_arch = "x86_64")]
        if let Some(simd) = self.sse {
            let at = items.as_ptr().wrapping_add(i);
            simd.sse
                ._mm_prefetch::<{ std::arch::x86_64::_MM_HINT_T0 }>(at.cast());
        }
        #[cfg(not(target_arch = "x86_64"))]
        let _ = (items, i);
    }
}

impl Default for Prefetcher {
    fn default() -> Self {
        Self::new()
    }
}
