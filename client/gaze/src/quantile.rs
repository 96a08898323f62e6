//! Quantiles of sorted samples: one definition for every figure foveal prints (the server's
//! per-second summary, `foveal watch` and `foveal load`, the benches, event agreement), so a p99
//! read in one place means the same as a p99 read in another.
//!
//! The definition is the **nearest rank** (Hyndman and Fan's type 1, the inverse of the
//! empirical distribution function): the `q`-quantile of `n` sorted values is the value of rank
//! `ceil(q n)` (1-based, at least 1), so it is always one of the samples, and the p99 of 100
//! values is the 99th. It lives in this crate because every other crate of the workspace depends
//! on it (as they do for its PRNG).

/// The `q`-quantile (`q` clamped to 0..=1) of `sorted` (ascending) by nearest rank, `None` when
/// empty.
#[must_use]
pub fn nearest_rank<T: Copy>(sorted: &[T], q: f64) -> Option<T> {
    if sorted.is_empty() {
        return None;
    }
    // `ceil(q n)` is an exact small integer in 0..=n.
    #[allow(
        clippy::cast_precision_loss,
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss
    )]
    let rank = (q.clamp(0.0, 1.0) * sorted.len() as f64).ceil() as usize;
    Some(sorted[rank.clamp(1, sorted.len()) - 1])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranks_are_the_nearest_rank_definition() {
        let v: Vec<u64> = (1..=100).collect();
        assert_eq!(nearest_rank(&v, 0.5), Some(50));
        assert_eq!(nearest_rank(&v, 0.99), Some(99));
        assert_eq!(nearest_rank(&v, 0.991), Some(100));
        assert_eq!(nearest_rank(&v, 1.0), Some(100));
        assert_eq!(nearest_rank(&v, 0.0), Some(1));
        assert_eq!(nearest_rank(&v, -3.0), Some(1));
        let w: Vec<f64> = (1..=200).map(f64::from).collect();
        assert_eq!(nearest_rank(&w, 0.99), Some(198.0));
        assert_eq!(nearest_rank(&w[..40], 0.99), Some(40.0));
        assert_eq!(nearest_rank(&[3.0], 0.99), Some(3.0));
        assert_eq!(nearest_rank::<f64>(&[], 0.5), None);
    }
}
