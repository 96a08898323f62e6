//! Bringing a collider's buffers back into cache before a timed frame.
//!
//! The server runs one collider, whose buffers stay in cache from one frame to the next. The
//! open-loop protocol (DESIGN.md) runs dozens of colliders in turn on the same frame, so each one
//! would otherwise start its timed frame with its own buffers evicted by the others, and a
//! wall-clock budget would charge a scheduler for the protocol's cache misses in proportion to the
//! memory it keeps, not for its work. The protocol calls [`crate::collider::Collider::warm`] (every
//! scheduler alike, outside the timed frame) to read each cache line of the collider's buffers
//! back. Nothing is written; no result depends on it.

/// Read one element per 64-byte cache line of `v` (and its last), so the lines are cached.
#[inline]
pub fn lines<T: Copy>(v: &[T]) {
    let step = (64 / std::mem::size_of::<T>().max(1)).max(1);
    for i in (0..v.len()).step_by(step) {
        std::hint::black_box(v[i]);
    }
    if let Some(&last) = v.last() {
        std::hint::black_box(last);
    }
}
