//! Event-level agreement between two lists of fixations, after Hooge, Niehorster, Nyström,
//! Andersson and Hessels (2018), "Is human classification by experienced untrained observers a
//! gold standard in fixation detection?", Behavior Research Methods 50.
//!
//! Events are matched one to one by overlap: every overlapping (detected, reference) pair is a
//! candidate, and pairs are taken greedily from the largest overlap down, each event at most once.
//! Precision is matched / detected, recall matched / reference, F1 their harmonic mean. For the
//! matched pairs, the onset difference is detected start minus reference start and the offset
//! difference detected end minus reference end; the median and the 90th percentile of their
//! absolute values are reported, with the signed median (a bias).

/// An interval of time, seconds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Interval {
    /// Start, seconds.
    pub start_s: f64,
    /// End, seconds (>= start).
    pub end_s: f64,
}

/// Summary statistics of one kind of timing difference over the matched pairs, seconds.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct TimingStats {
    /// Median of the absolute differences.
    pub median_abs_s: f64,
    /// 90th percentile (nearest rank) of the absolute differences.
    pub p90_abs_s: f64,
    /// Median of the signed differences (detected minus reference).
    pub median_signed_s: f64,
}

/// Agreement of a detected list with a reference list.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Agreement {
    /// Detected events.
    pub detected: usize,
    /// Reference events.
    pub reference: usize,
    /// Matched pairs.
    pub matched: usize,
    /// matched / detected (0 with no detection).
    pub precision: f64,
    /// matched / reference (0 with no reference).
    pub recall: f64,
    /// Harmonic mean of precision and recall (0 when both are 0).
    pub f1: f64,
    /// Onset differences of the matched pairs.
    pub onset: TimingStats,
    /// Offset differences of the matched pairs.
    pub offset: TimingStats,
}

fn ratio(a: usize, b: usize) -> f64 {
    if b == 0 {
        0.0
    } else {
        #[allow(clippy::cast_precision_loss)]
        let r = a as f64 / b as f64;
        r
    }
}

/// The value at quantile `q` (nearest rank, [`crate::quantile`]) of `sorted`, 0 when empty.
fn nearest_rank(sorted: &[f64], q: f64) -> f64 {
    crate::quantile::nearest_rank(sorted, q).unwrap_or(0.0)
}

fn median(sorted: &[f64]) -> f64 {
    match sorted.len() {
        0 => 0.0,
        n if n % 2 == 1 => sorted[n / 2],
        n => (sorted[n / 2 - 1] + sorted[n / 2]) / 2.0,
    }
}

fn stats(diffs: &[f64]) -> TimingStats {
    let mut abs: Vec<f64> = diffs.iter().map(|d| d.abs()).collect();
    abs.sort_by(f64::total_cmp);
    let mut signed = diffs.to_vec();
    signed.sort_by(f64::total_cmp);
    TimingStats {
        median_abs_s: median(&abs),
        p90_abs_s: nearest_rank(&abs, 0.9),
        median_signed_s: median(&signed),
    }
}

/// The matched pairs, as (detected index, reference index), in reference order.
#[must_use]
pub fn match_events(detected: &[Interval], reference: &[Interval]) -> Vec<(usize, usize)> {
    let mut candidates = Vec::new();
    for (i, d) in detected.iter().enumerate() {
        // Reference lists are sorted in practice, but nothing here relies on it.
        for (j, r) in reference.iter().enumerate() {
            let overlap = d.end_s.min(r.end_s) - d.start_s.max(r.start_s);
            if overlap >= 0.0 {
                candidates.push((overlap, i, j));
            }
        }
    }
    candidates.sort_by(|a, b| b.0.total_cmp(&a.0).then(a.1.cmp(&b.1)).then(a.2.cmp(&b.2)));
    let mut used_d = vec![false; detected.len()];
    let mut used_r = vec![false; reference.len()];
    let mut pairs = Vec::new();
    for (_, i, j) in candidates {
        if !used_d[i] && !used_r[j] {
            used_d[i] = true;
            used_r[j] = true;
            pairs.push((i, j));
        }
    }
    pairs.sort_by_key(|&(_, j)| j);
    pairs
}

/// Agreement of `detected` with `reference`.
#[must_use]
pub fn compare(detected: &[Interval], reference: &[Interval]) -> Agreement {
    compare_groups(&[(detected, reference)])
}

/// Agreement pooled over groups that must not match across one another (the eyes of a
/// binocular recording: a left-eye detection may only match a left-eye reference fixation).
/// Events are matched within each `(detected, reference)` group; the counts and the timing
/// differences of all groups are then pooled, so each event counts once, as in [`compare`].
#[must_use]
pub fn compare_groups(groups: &[(&[Interval], &[Interval])]) -> Agreement {
    let (mut detected, mut reference, mut matched) = (0, 0, 0);
    let (mut onsets, mut offsets) = (Vec::new(), Vec::new());
    for &(d, r) in groups {
        let pairs = match_events(d, r);
        detected += d.len();
        reference += r.len();
        matched += pairs.len();
        onsets.extend(pairs.iter().map(|&(i, j)| d[i].start_s - r[j].start_s));
        offsets.extend(pairs.iter().map(|&(i, j)| d[i].end_s - r[j].end_s));
    }
    let precision = ratio(matched, detected);
    let recall = ratio(matched, reference);
    let f1 = if precision + recall > 0.0 {
        2.0 * precision * recall / (precision + recall)
    } else {
        0.0
    };
    Agreement {
        detected,
        reference,
        matched,
        precision,
        recall,
        f1,
        onset: stats(&onsets),
        offset: stats(&offsets),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn iv(start_s: f64, end_s: f64) -> Interval {
        Interval { start_s, end_s }
    }

    #[test]
    fn exact_scores_on_a_small_case() {
        let reference = [iv(0.0, 1.0), iv(1.2, 2.0), iv(3.0, 4.0)];
        // One good match, one split in two (only the larger half matches), one false alarm,
        // one reference event missed.
        let detected = [iv(0.01, 0.99), iv(1.2, 1.5), iv(1.55, 2.04), iv(5.0, 6.0)];
        let a = compare(&detected, &reference);
        assert_eq!((a.detected, a.reference, a.matched), (4, 3, 2));
        assert_eq!(match_events(&detected, &reference), vec![(0, 0), (2, 1)]);
        assert_eq!(a.precision, 0.5);
        assert!((a.recall - 2.0 / 3.0).abs() < 1e-15);
        assert!((a.f1 - 4.0 / 7.0).abs() < 1e-15);
        // Onsets: +0.01 and +0.35; offsets: -0.01 and +0.04.
        assert!((a.onset.median_abs_s - 0.18).abs() < 1e-12);
        assert!((a.onset.p90_abs_s - 0.35).abs() < 1e-12);
        assert!((a.offset.median_signed_s - 0.015).abs() < 1e-12);
        assert!((a.offset.p90_abs_s - 0.04).abs() < 1e-12);
    }

    #[test]
    fn groups_never_match_across_one_another() {
        // Each group's detection lies on the other group's reference: pooled into one list they
        // would match perfectly, kept apart nothing matches.
        let (d0, r0) = ([iv(0.0, 1.0)], [iv(2.0, 3.0)]);
        let (d1, r1) = ([iv(2.0, 3.0)], [iv(0.0, 1.0)]);
        let a = compare_groups(&[(&d0, &r0), (&d1, &r1)]);
        assert_eq!((a.detected, a.reference, a.matched), (2, 2, 0));
        // One group is exactly `compare`.
        let one = compare_groups(&[(&d0, &r1)]);
        assert_eq!(one, compare(&d0, &r1));
        assert_eq!(one.f1, 1.0);
    }

    #[test]
    fn empty_lists_score_zero() {
        let a = compare(&[], &[iv(0.0, 1.0)]);
        assert_eq!((a.precision, a.recall, a.f1), (0.0, 0.0, 0.0));
        let same = [iv(0.0, 1.0), iv(2.0, 3.0)];
        let a = compare(&same, &same);
        assert_eq!((a.precision, a.recall, a.f1), (1.0, 1.0, 1.0));
        assert_eq!(a.onset, TimingStats::default());
    }
}
