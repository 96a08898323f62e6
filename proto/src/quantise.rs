//! Quantised poses and packed collision lists for `WatchFrames` viewers.
//!
//! A viewer at N = 10,000 receives 280 KB per frame as f32 poses, 17 MB/s at 60 Hz: more than a
//! browser decodes comfortably, for precision nobody can see. [`pb::QuantisedPoses`] carries a
//! position as three u16 over the volume (error at most side / 131,070 per axis) and an orientation
//! as "smallest three" in one u32 (the largest component dropped and rebuilt from the unit norm,
//! the other three in 10 bits each, rotation error under a quarter of a degree): 10 bytes per body instead of 28.
//! The wire layout is specified on the messages in `foveal.proto`; this module is its one encoder.

use crate::pb;

/// Largest 10-bit code of a smallest-three component.
const Q10: f32 = 1023.0;
/// Largest 16-bit code of a position coordinate.
const Q16: f32 = 65535.0;

/// Bytes per body of [`pb::QuantisedPoses`] (6 position + 4 orientation).
pub const QUANTISED_BYTES_PER_BODY: usize = 10;

/// Encode one position coordinate `v` (relative to the volume origin) over `[0, extent]`.
fn quantise_coordinate(v: f32, extent: f32) -> u16 {
    if extent.is_nan() || extent <= 0.0 || !v.is_finite() {
        return 0;
    }
    // Clamped: a centre a hair outside the volume (walls reflect after the step) is drawn on it.
    let t = (v / extent).clamp(0.0, 1.0);
    // In [0, 65535] after the clamp, so the cast is exact rounding, never a wrap.
    (t * Q16).round() as u16
}

/// Encode a unit quaternion (x, y, z, w) as smallest three in one u32. A quaternion that is not
/// finite or has zero length encodes the identity.
pub fn quantise_quaternion(q: [f32; 4]) -> u32 {
    let len2: f32 = q.iter().map(|c| c * c).sum();
    if !len2.is_finite() || len2 <= f32::MIN_POSITIVE {
        return quantise_quaternion([0.0, 0.0, 0.0, 1.0]);
    }
    let inv = len2.sqrt().recip();
    let mut q = q.map(|c| c * inv);
    let mut largest = 0;
    for i in 1..4 {
        if q[i].abs() > q[largest].abs() {
            largest = i;
        }
    }
    // q and -q are the same rotation: make the dropped component positive so its sign need not
    // travel.
    if q[largest] < 0.0 {
        q = q.map(|c| -c);
    }
    let mut bits = (largest as u32) << 30;
    let mut shift = 20;
    for (i, c) in q.iter().enumerate() {
        if i == largest {
            continue;
        }
        let t = ((c * std::f32::consts::SQRT_2 + 1.0) * 0.5).clamp(0.0, 1.0);
        bits |= ((t * Q10).round() as u32) << shift;
        shift -= 10;
    }
    bits
}

/// Decode [`quantise_quaternion`]'s u32 into a unit quaternion (x, y, z, w).
pub fn dequantise_quaternion(bits: u32) -> [f32; 4] {
    let largest = (bits >> 30) as usize;
    let mut q = [0.0f32; 4];
    let mut shift = 20;
    let mut sum = 0.0;
    for (i, c) in q.iter_mut().enumerate() {
        if i == largest {
            continue;
        }
        let v = ((bits >> shift) & 0x3ff) as f32;
        *c = (v / Q10 * 2.0 - 1.0) * std::f32::consts::FRAC_1_SQRT_2;
        sum += *c * *c;
        shift -= 10;
    }
    q[largest] = (1.0 - sum).max(0.0).sqrt();
    q
}

impl pb::QuantisedPoses {
    /// Quantise positions (relative to `origin`, inside the cube of side `extent`) and unit
    /// quaternions (x, y, z, w).
    pub fn pack(
        origin: pb::Vec3,
        extent: f64,
        positions: impl ExactSizeIterator<Item = [f32; 3]>,
        orientations: impl Iterator<Item = [f32; 4]>,
    ) -> Self {
        let bodies = positions.len();
        let side = extent as f32;
        let mut pos = Vec::with_capacity(6 * bodies);
        for p in positions {
            for v in p {
                pos.extend_from_slice(&quantise_coordinate(v, side).to_le_bytes());
            }
        }
        let mut rot = Vec::with_capacity(4 * bodies);
        for q in orientations {
            rot.extend_from_slice(&quantise_quaternion(q).to_le_bytes());
        }
        Self {
            positions: pos.into(),
            orientations: rot.into(),
            origin: Some(origin),
            extent,
            bodies: u32::try_from(bodies).unwrap_or(u32::MAX),
        }
    }

    /// Positions relative to `origin`, one (x, y, z) per body.
    pub fn positions_f32(&self) -> impl Iterator<Item = [f32; 3]> + '_ {
        let scale = self.extent as f32 / Q16;
        self.positions.chunks_exact(6).map(move |c| {
            [0, 2, 4].map(|i| f32::from(u16::from_le_bytes([c[i], c[i + 1]])) * scale)
        })
    }

    /// Orientations, one unit quaternion (x, y, z, w) per body.
    pub fn orientations_f32(&self) -> impl Iterator<Item = [f32; 4]> + '_ {
        self.orientations
            .chunks_exact(4)
            .map(|c| dequantise_quaternion(u32::from_le_bytes([c[0], c[1], c[2], c[3]])))
    }
}

impl pb::Collisions {
    /// Pack the real and the deemed pairs of a collision list.
    pub fn pack(
        real: impl Iterator<Item = (u32, u32)>,
        deemed: impl Iterator<Item = (u32, u32)>,
    ) -> Self {
        fn bytes(pairs: impl Iterator<Item = (u32, u32)>) -> Vec<u8> {
            let mut out = Vec::new();
            for (a, b) in pairs {
                out.extend_from_slice(&a.to_le_bytes());
                out.extend_from_slice(&b.to_le_bytes());
            }
            out
        }
        Self {
            real: bytes(real).into(),
            deemed: bytes(deemed).into(),
            deemed_truth: Default::default(),
        }
    }

    /// The same list with an audit's answer for each deemed pair, in the order of the deemed
    /// pairs (`Collisions.deemed_truth`: 0 not audited, 1 colliding, 2 apart).
    pub fn with_deemed_truth(mut self, truth: impl Iterator<Item = u8>) -> Self {
        self.deemed_truth = truth.collect::<Vec<u8>>().into();
        self
    }

    /// The deemed pairs with what the frame's audit found of each (0 not audited, 1 colliding,
    /// 2 apart; 0 for every pair of an unaudited frame).
    pub fn deemed_with_truth(&self) -> impl Iterator<Item = ((u32, u32), u8)> + '_ {
        let truth = self
            .deemed_truth
            .iter()
            .copied()
            .chain(std::iter::repeat(0));
        pairs(&self.deemed).zip(truth)
    }

    /// The pairs resolved as colliding.
    pub fn real_pairs(&self) -> impl Iterator<Item = (u32, u32)> + '_ {
        pairs(&self.real)
    }

    /// The pairs deemed colliding at interruption.
    pub fn deemed_pairs(&self) -> impl Iterator<Item = (u32, u32)> + '_ {
        pairs(&self.deemed)
    }
}

fn pairs(b: &[u8]) -> impl Iterator<Item = (u32, u32)> + '_ {
    b.chunks_exact(8).map(|c| {
        (
            u32::from_le_bytes([c[0], c[1], c[2], c[3]]),
            u32::from_le_bytes([c[4], c[5], c[6], c[7]]),
        )
    })
}

#[cfg(test)]
mod tests {
    use prost::Message;

    use super::*;

    /// Angle in degrees between the rotations of two unit quaternions.
    fn angle_deg(a: [f32; 4], b: [f32; 4]) -> f32 {
        let dot: f32 = a.iter().zip(b).map(|(x, y)| x * y).sum();
        2.0 * dot.abs().min(1.0).acos().to_degrees()
    }

    /// A deterministic spread of unit quaternions (and their negations) covering every
    /// largest-component case.
    fn quaternions() -> Vec<[f32; 4]> {
        let mut out = Vec::new();
        let mut s = 0x2545_f491_u32;
        let mut next = || {
            s ^= s << 13;
            s ^= s >> 17;
            s ^= s << 5;
            (s as f32 / u32::MAX as f32) * 2.0 - 1.0
        };
        for _ in 0..5000 {
            let q = [next(), next(), next(), next()];
            let l = q.iter().map(|c| c * c).sum::<f32>().sqrt();
            if l > 1e-3 {
                out.push(q.map(|c| c / l));
            }
        }
        out.extend([
            [0.0, 0.0, 0.0, 1.0],
            [0.0, 0.0, 0.0, -1.0],
            [1.0, 0.0, 0.0, 0.0],
            [0.0, -1.0, 0.0, 0.0],
            [0.5, 0.5, 0.5, 0.5],
            [
                std::f32::consts::FRAC_1_SQRT_2,
                0.0,
                0.0,
                std::f32::consts::FRAC_1_SQRT_2,
            ],
        ]);
        out
    }

    #[test]
    fn quaternions_come_back_within_a_quarter_of_a_degree() {
        let mut worst = 0.0f32;
        for q in quaternions() {
            let back = dequantise_quaternion(quantise_quaternion(q));
            let norm: f32 = back.iter().map(|c| c * c).sum();
            assert!(
                (norm - 1.0).abs() < 1e-3,
                "{q:?} -> {back:?} has norm² {norm}"
            );
            worst = worst.max(angle_deg(q, back));
        }
        assert!(worst < 0.25, "worst rotation error {worst} degrees");
    }

    #[test]
    fn degenerate_quaternions_encode_the_identity() {
        for q in [
            [0.0; 4],
            [f32::NAN, 0.0, 0.0, 1.0],
            [f32::INFINITY, 0.0, 0.0, 0.0],
        ] {
            let back = dequantise_quaternion(quantise_quaternion(q));
            assert!(
                angle_deg(back, [0.0, 0.0, 0.0, 1.0]) < 0.25,
                "{q:?} -> {back:?}"
            );
        }
    }

    #[test]
    fn positions_come_back_within_half_a_step_and_outliers_clamp() {
        let extent = 10.0;
        let positions = vec![
            [0.0, 10.0, 5.0],
            [1.234_567, 9.876_543, 0.000_1],
            [-0.01, 10.02, f32::NAN],
        ];
        let poses = pb::QuantisedPoses::pack(
            pb::Vec3::default(),
            extent,
            positions.clone().into_iter(),
            std::iter::repeat_n([0.0, 0.0, 0.0, 1.0], positions.len()),
        );
        let back: Vec<[f32; 3]> = poses.positions_f32().collect();
        let step = extent as f32 / 65535.0;
        for (p, b) in positions[..2].iter().zip(&back) {
            for (v, w) in p.iter().zip(b) {
                assert!((v - w).abs() <= step * 0.5 + 1e-6, "{v} came back as {w}");
            }
        }
        assert_eq!(
            back[2],
            [0.0, 10.0, 0.0],
            "clamped to the volume, NaN to its origin"
        );
    }

    #[test]
    fn a_frame_of_quantised_poses_is_under_half_the_bytes_and_round_trips() {
        let n = 10_000usize;
        let extent = 10.0f64;
        let positions: Vec<[f32; 3]> = (0..n)
            .map(|i| {
                let f = i as f32 / n as f32;
                [
                    f * 10.0,
                    (f * 37.0).fract() * 10.0,
                    (f * 101.0).fract() * 10.0,
                ]
            })
            .collect();
        let orientations: Vec<[f32; 4]> = quaternions().into_iter().cycle().take(n).collect();
        let origin = pb::Vec3 {
            x: -5.0,
            y: -5.0,
            z: -5.0,
        };
        let full = pb::Frame {
            index: 3,
            poses: Some(pb::Poses::pack(
                origin,
                positions.iter().copied(),
                orientations.iter().copied(),
            )),
            ..Default::default()
        };
        let quantised = pb::Frame {
            index: 3,
            quantised_poses: Some(pb::QuantisedPoses::pack(
                origin,
                extent,
                positions.iter().copied(),
                orientations.iter().copied(),
            )),
            ..Default::default()
        };
        let (full_bytes, q_bytes) = (full.encoded_len(), quantised.encoded_len());
        assert!(
            q_bytes * 2 <= full_bytes,
            "quantised frame {q_bytes} B vs f32 frame {full_bytes} B"
        );
        assert!(q_bytes <= n * QUANTISED_BYTES_PER_BODY + 64, "{q_bytes} B");

        let back = pb::Frame::decode(quantised.encode_to_vec().as_slice()).expect("decodes");
        assert_eq!(back, quantised);
        let poses = back.quantised_poses.expect("quantised poses");
        assert_eq!(poses.bodies as usize, n);
        assert_eq!(poses.origin, Some(origin));
        let step = extent as f32 / 65535.0;
        for (p, b) in positions.iter().zip(poses.positions_f32()) {
            for (v, w) in p.iter().zip(b) {
                assert!((v - w).abs() <= step * 0.5 + 1e-5, "{v} came back as {w}");
            }
        }
        for (q, b) in orientations.iter().zip(poses.orientations_f32()) {
            assert!(angle_deg(*q, b) < 0.25, "{q:?} came back as {b:?}");
        }
    }

    #[test]
    fn collisions_round_trip_real_and_deemed_apart() {
        let c = pb::Collisions::pack([(0, 1), (7, u32::MAX)].into_iter(), [(2, 3)].into_iter());
        let back = pb::Collisions::decode(c.encode_to_vec().as_slice()).expect("decodes");
        assert_eq!(
            back.real_pairs().collect::<Vec<_>>(),
            vec![(0, 1), (7, u32::MAX)]
        );
        assert_eq!(back.deemed_pairs().collect::<Vec<_>>(), vec![(2, 3)]);
        assert_eq!(pb::Collisions::default().real_pairs().count(), 0);
    }

    #[test]
    fn deemed_pairs_carry_their_truth_in_order_and_an_unaudited_list_reads_as_not_audited() {
        let c = pb::Collisions::pack([].into_iter(), [(2, 3), (4, 5), (6, 7)].into_iter())
            .with_deemed_truth([2, 1, 0].into_iter());
        let back = pb::Collisions::decode(c.encode_to_vec().as_slice()).expect("decodes");
        assert_eq!(
            back.deemed_with_truth().collect::<Vec<_>>(),
            vec![((2, 3), 2), ((4, 5), 1), ((6, 7), 0)]
        );
        let plain = pb::Collisions::pack([].into_iter(), [(2, 3)].into_iter());
        assert_eq!(
            plain.deemed_with_truth().collect::<Vec<_>>(),
            vec![((2, 3), 0)]
        );
    }
}
