//! The engine's star contact (`star_contact`: closed forms, GJK and EPA) held to an independent
//! judge: branch and bound over patches of the two stars' surfaces, written apart from the engine
//! (`server/bench/src/shape_oracle.rs`, included here by path; `foveal-bench shape-check` runs
//! the same judge over whole scenes at full size).
//!
//! Where the judge is sure (a sample of one star inside the other, or a proven distance beyond
//! the touching tolerance) the engine must agree; where it is not (a contact within the judge's
//! bracket of grazing) nothing is asserted and the case is counted. For pairs proven apart the
//! engine's gap must lie in the judge's bracket and its closest points on the two surfaces; for
//! overlapping pairs, moving B along the engine's normal by the depth must part them and by half
//! the depth must not.
//!
//! Some of these fail on the engine as it is, and are kept, ignored, until it is fixed (each
//! `#[ignore]` names its case): the gap, the closest points, the swap symmetry and grazing
//! answers (GJK stops on a repeated support point before it converges:
//! `gjk_stops_early_on_a_repeated_support_point`; or reads a flat simplex as enclosing the
//! origin: `gjk_reads_a_flat_simplex_as_enclosing`), and moving by the depth
//! (`moving_by_the_depth_parts_the_stars_pinned`). `cargo test -- --ignored` runs them.

#[allow(dead_code)]
#[path = "../../bench/src/shape_oracle.rs"]
mod oracle;

use foveal_engine::narrow_phase::PairStatus;
use foveal_engine::shape::Star;
use foveal_engine::star_contact::{Contact, Pose, StarGeometry, TOUCH_TOLERANCE};
use foveal_engine::{BudgetSpec, FrozenClock, SimConfig, Simulation, Truth};
use glam::{DMat3, DQuat, DVec3};
use oracle::{Judgement, Oracle, Placement, V3, Verdict};
use proptest::prelude::*;

/// The scene's default bounding radius.
const R: f64 = 0.2;

fn v3(v: DVec3) -> V3 {
    V3::new(v.x, v.y, v.z)
}

fn placement(pose: &Pose) -> Placement {
    let m = pose.rotation;
    Placement {
        centre: v3(pose.translation),
        axes: [v3(m.x_axis), v3(m.y_axis), v3(m.z_axis)],
    }
}

/// A pose as the report of a failure gives it: rotation (rows), translation, R.
fn show(pose: &Pose) -> String {
    let m = pose.rotation.transpose();
    format!(
        "R = {R}, rotation rows [{:?}, {:?}, {:?}], translation {:?}",
        m.x_axis.to_array(),
        m.y_axis.to_array(),
        m.z_axis.to_array(),
        pose.translation.to_array()
    )
}

/// A uniform random rotation from three uniforms in [0, 1) (Shoemake's method).
fn uniform_rotation(u: [f64; 3]) -> DQuat {
    let tau = std::f64::consts::TAU;
    let (a, b) = ((1.0 - u[0]).sqrt(), u[0].sqrt());
    DQuat::from_xyzw(
        a * (tau * u[1]).sin(),
        a * (tau * u[1]).cos(),
        b * (tau * u[2]).sin(),
        b * (tau * u[2]).cos(),
    )
    .normalize()
}

/// A direction uniform on the sphere from two uniforms in [0, 1).
fn uniform_direction(u: [f64; 2]) -> DVec3 {
    let z = 2.0 * u[0] - 1.0;
    let phi = std::f64::consts::TAU * u[1];
    let s = (1.0 - z * z).max(0.0).sqrt();
    DVec3::new(s * phi.cos(), s * phi.sin(), z)
}

fn pose(rotation: DQuat, translation: DVec3) -> Pose {
    Pose {
        rotation: DMat3::from_quat(rotation),
        translation,
    }
}

/// B's frame seen from A becomes A's frame seen from B.
fn inverse(p: &Pose) -> Pose {
    let mt = p.rotation.transpose();
    Pose {
        rotation: mt,
        translation: -(mt * p.translation),
    }
}

/// Spike `k` of a star (0 +x, 1 -x, 2 +y, 3 -y, 4 +z, 5 -z), in its own frame.
fn spike_axis(k: usize) -> DVec3 {
    let a = [DVec3::X, DVec3::Y, DVec3::Z][k / 2];
    if k.is_multiple_of(2) { a } else { -a }
}

fn geometry() -> StarGeometry {
    StarGeometry::new(Star::new(R))
}

/// What a check found: the judge's and the engine's answers, and what is wrong with the
/// engine's, each error naming the pose.
#[derive(Debug, Clone)]
struct Checked {
    judged: Judgement,
    contact: Contact,
    /// The engine's touching answers disagree with each other or with a sure judgement.
    answer: Option<String>,
    /// A proven-apart pair's gap lies outside the judge's bracket (beyond the tolerance).
    gap: Option<String>,
    /// A proven-apart pair's closest points are off the surfaces or not the gap apart.
    points: Option<String>,
}

impl Checked {
    /// Fail the test on a wrong answer.
    fn assert_answer(&self) {
        if let Some(e) = &self.answer {
            panic!("{e}");
        }
    }

    /// Fail the test on a gap outside the judge's bracket or wrong closest points too.
    fn assert_all(&self) {
        let first = [&self.answer, &self.gap, &self.points]
            .into_iter()
            .flatten()
            .next();
        if let Some(e) = first {
            panic!("{e}");
        }
    }
}

/// Hold the engine to the judge at `pose`: the engine's two answers agree with each other, and
/// with the judge wherever the judge is sure; for a pair proven apart, the gap lies in the
/// judge's bracket and the closest points are on the surfaces, the gap apart.
fn check(pose: &Pose) -> Checked {
    let g = geometry();
    let o = Oracle::new(R);
    let b = placement(pose);
    let judged = o.judge(&b);
    let hit = g.intersects(pose);
    let contact = g.contact(pose);
    let at = show(pose);
    let error = |what: String| Some(format!("{what}: {at}"));
    let mut c = Checked {
        judged,
        contact,
        answer: None,
        gap: None,
        points: None,
    };
    if hit != contact.is_touching() {
        c.answer = error(format!("intersects says {hit}, contact {contact:?}"));
    }
    let tol = TOUCH_TOLERANCE * R;
    match judged.verdict {
        Verdict::Touching if !hit => {
            c.answer = error(format!(
                "the judge finds them touching, the engine {contact:?}"
            ));
        }
        Verdict::Apart if hit => {
            c.answer = error(format!(
                "the judge proves them {} apart, the engine touching",
                judged.lower
            ));
        }
        Verdict::Apart => {
            let gap = contact.gap();
            if gap < judged.lower - tol || gap > judged.upper + tol {
                c.gap = error(format!(
                    "gap {gap} outside the judge's [{}, {}]",
                    judged.lower, judged.upper
                ));
            }
            if let Contact::Apart {
                distance,
                point_a,
                point_b,
            } = contact
            {
                let (pa, pb) = (v3(point_a), v3(point_b));
                let n = (pb - pa) * (1.0 / (pb - pa).norm());
                // Each point is in its star (within the tolerance) and a tolerance's step
                // towards the other star leaves it: it is within the tolerance of the surface.
                if ((pb - pa).norm() - distance).abs() > tol {
                    c.points = error(format!("closest points not {distance} apart: {contact:?}"));
                } else if o.distance(pa) > tol || o.distance(pa + n * tol) <= 0.0 {
                    c.points = error(format!("A's closest point off A's surface: {contact:?}"));
                } else if o.distance_to(&b, pb) > tol || o.distance_to(&b, pb - n * tol) <= 0.0 {
                    c.points = error(format!("B's closest point off B's surface: {contact:?}"));
                }
            }
        }
        _ => {}
    }
    c
}

/// [`check`], failing the test on a wrong answer.
fn checked(pose: &Pose) -> Checked {
    let c = check(pose);
    c.assert_answer();
    c
}

/// For an overlapping pair, B moved along the engine's normal by `fraction` of the depth and
/// `extra` more, as the judge sees it (None when the engine finds no depth).
fn moved_by_depth(pose: &Pose, c: &Contact, fraction: f64, extra: f64) -> Option<Judgement> {
    let Contact::Touching { normal, depth, .. } = *c else {
        return None;
    };
    if depth <= 0.0 {
        return None;
    }
    let moved = Pose {
        translation: pose.translation + normal * (fraction * depth + extra),
        ..*pose
    };
    Some(Oracle::new(R).judge(&placement(&moved)))
}

/// Moving B along the engine's normal by the depth and 1e-6 R parts the stars.
fn depth_parts(pose: &Pose, c: &Contact) -> Result<(), String> {
    match moved_by_depth(pose, c, 1.0, 1e-6 * R) {
        Some(j) if j.verdict == Verdict::Touching => Err(format!(
            "moved by the depth along the normal, still touching: {c:?} at {}",
            show(pose)
        )),
        _ => Ok(()),
    }
}

/// Moving B along the engine's normal by half the depth leaves the stars touching.
fn half_depth_touches(pose: &Pose, c: &Contact) -> Result<(), String> {
    match moved_by_depth(pose, c, 0.5, 0.0) {
        Some(j) if j.verdict == Verdict::Apart => Err(format!(
            "moved by half the depth along the normal, apart by {}: {c:?} at {}",
            j.lower,
            show(pose)
        )),
        _ => Ok(()),
    }
}

#[test]
fn the_judge_measures_the_engines_star() {
    let star = Star::new(R);
    let o = Oracle::new(R);
    assert_eq!(o.core(), star.core_radius);
    assert_eq!(o.base(), star.spike_base_radius);
    assert_eq!(o.radius(), star.radius);
    // The engine's own point test (the octree's, not the contact's) agrees off the surface.
    let mut u = Uniforms(0x57a2);
    for _ in 0..20_000 {
        let p = DVec3::from_array(u.three_in(1.1 * R));
        let d = o.distance(v3(p));
        if d.abs() > 1e-12 {
            assert_eq!(star.contains(p), d <= 0.0, "{p}");
        }
    }
}

/// A uniform rotation and a translation of length `dist` R in a uniform direction.
fn random_pose(q: [f64; 3], dir: [f64; 2], dist: f64) -> Pose {
    pose(uniform_rotation(q), uniform_direction(dir) * dist * R)
}

/// `base` with B moved along the engine's normal to the engine's own grazing distance, then by
/// `off` R.
fn grazing_pose(base: &Pose, off: f64) -> Pose {
    let c = geometry().contact(base);
    Pose {
        translation: base.translation + c.normal() * (off * R - c.signed_distance()),
        ..*base
    }
}

/// A's spike `ka` tip against B's spike `kb` tip: the axes anti-aligned, then B turned by
/// `angle` about a uniform axis, its centre shifted by `shift` R from the exact meeting.
fn tips_pose(
    ka: usize,
    kb: usize,
    q: [f64; 3],
    axis: [f64; 2],
    angle: f64,
    shift: [f64; 3],
) -> Pose {
    let (a, b) = (spike_axis(ka), spike_axis(kb));
    let spin = uniform_rotation(q);
    let turn = DQuat::from_rotation_arc(spin * b, -a) * spin;
    let rot = DQuat::from_axis_angle(uniform_direction(axis), angle) * turn;
    pose(rot, a * 2.0 * R + DVec3::from_array(shift) * R)
}

/// A's spike `ka` tip against B's core: B's centre (1.3 + `along`) R along the spike, shifted by
/// `shift` R, B at any rotation (its spikes may reach in too).
fn tip_core_pose(ka: usize, q: [f64; 3], along: f64, shift: [f64; 3]) -> Pose {
    let a = spike_axis(ka);
    pose(
        uniform_rotation(q),
        a * (1.3 + along) * R + DVec3::from_array(shift) * R,
    )
}

/// A's spike `ka` flank against B's spike `kb` flank: B's axis at angle `around` about A's and
/// tilted by `tilt` rad from the perpendicular, the two axes crossing at heights `u` R (A) and
/// `s` R (B), their common perpendicular the sum of the cones' radii there times
/// (1 + `slack`).
#[allow(clippy::too_many_arguments)]
fn flanks_pose(
    ka: usize,
    kb: usize,
    q: [f64; 3],
    around: f64,
    tilt: f64,
    u: f64,
    s: f64,
    slack: f64,
) -> Pose {
    let a = spike_axis(ka);
    let e1 = a.any_orthonormal_vector();
    let e2 = a.cross(e1);
    let phi = std::f64::consts::TAU * around;
    let d = (e1 * phi.cos() + e2 * phi.sin()) * tilt.cos() + a * tilt.sin();
    let spin = uniform_rotation(q);
    let rot = DQuat::from_rotation_arc(spin * spike_axis(kb), d) * spin;
    let n = a.cross(d).normalize();
    let w = 0.25 * R * ((1.0 - u) + (1.0 - s)) * (1.0 + slack);
    pose(rot, a * u * R + n * w - d * s * R)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Uniform rotations, translations up to 2.2R in a uniform direction.
    #[test]
    fn random_poses_agree(
        q in prop::array::uniform3(0.0f64..1.0),
        dir in prop::array::uniform2(0.0f64..1.0),
        dist in 0.0f64..2.2,
    ) {
        checked(&random_pose(q, dir, dist));
    }

    /// Spike tip against spike tip, the axes anti-aligned up to 0.05 rad, the tips within a few
    /// hundredths of R.
    #[test]
    fn spike_tips_agree(
        ka in 0usize..6, kb in 0usize..6,
        q in prop::array::uniform3(0.0f64..1.0),
        axis in prop::array::uniform2(0.0f64..1.0), angle in -0.05f64..0.05,
        shift in prop::array::uniform3(-0.02f64..0.02),
    ) {
        checked(&tips_pose(ka, kb, q, axis, angle, shift));
    }

    /// A spike tip of A against B's core.
    #[test]
    fn spike_tip_against_core_agrees(
        ka in 0usize..6,
        q in prop::array::uniform3(0.0f64..1.0),
        along in -0.06f64..0.06,
        shift in prop::array::uniform3(-0.05f64..0.05),
    ) {
        checked(&tip_core_pose(ka, q, along, shift));
    }

    /// Spike flank against spike flank, the axes crossing nearly at right angles.
    #[test]
    fn spike_flanks_agree(
        ka in 0usize..6, kb in 0usize..6,
        q in prop::array::uniform3(0.0f64..1.0),
        around in 0.0f64..1.0, tilt in -0.2f64..0.2,
        u in 0.1f64..0.9, s in 0.1f64..0.9, slack in -0.1f64..0.1,
    ) {
        checked(&flanks_pose(ka, kb, q, around, tilt, u, s, slack));
    }

    /// Coincident centres always touch.
    #[test]
    fn coincident_centres_touch(q in prop::array::uniform3(0.0f64..1.0)) {
        let c = checked(&pose(uniform_rotation(q), DVec3::ZERO));
        prop_assert_eq!(c.judged.verdict, Verdict::Touching);
        prop_assert!(c.contact.is_touching());
    }

    /// Moving B along the engine's normal by half the depth leaves the stars touching.
    #[test]
    fn half_the_depth_leaves_them_touching(
        q in prop::array::uniform3(0.0f64..1.0),
        dir in prop::array::uniform2(0.0f64..1.0),
        dist in 0.0f64..2.0,
    ) {
        let p = random_pose(q, dir, dist);
        let c = geometry().contact(&p);
        half_depth_touches(&p, &c).unwrap_or_else(|e| panic!("{e}"));
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// B at the engine's own grazing distance along its normal, then 1e-6 R or 1e-7 R either
    /// way: engine and judge agree wherever the judge is sure.
    ///
    /// Ignored: fails. GJK (cone against cone) stops when a support point repeats and returns
    /// |v| as the distance although its proven lower bound is negative: the engine calls
    /// overlapping stars apart, or reports a gap up to ~4e-7 R too large. Pinned poses in
    /// `gjk_stops_early_on_a_repeated_support_point`.
    #[test]
    #[ignore = "engine: GJK stops on a repeated support point (see gjk_stops_early_on_a_repeated_support_point)"]
    fn grazing_contacts_agree(
        q in prop::array::uniform3(0.0f64..1.0),
        dir in prop::array::uniform2(0.0f64..1.0),
        dist in 0.3f64..2.2,
        off in prop::sample::select(vec![-1e-6, 1e-6, -1e-7, 1e-7]),
    ) {
        check(&grazing_pose(&random_pose(q, dir, dist), off)).assert_all();
    }

    /// Random poses' gaps lie within 1e-9 R of the judge's bracket, their closest points on the
    /// surfaces.
    ///
    /// Ignored: fails (about 2% of poses, up to 5e-8 R too large) with the GJK early stop of
    /// `gjk_stops_early_on_a_repeated_support_point`.
    #[test]
    #[ignore = "engine: GJK stops on a repeated support point (see gjk_stops_early_on_a_repeated_support_point)"]
    fn random_poses_have_the_judges_gaps(
        q in prop::array::uniform3(0.0f64..1.0),
        dir in prop::array::uniform2(0.0f64..1.0),
        dist in 0.0f64..2.2,
    ) {
        check(&random_pose(q, dir, dist)).assert_all();
    }

    /// Swapping A and B (the inverse pose) gives the same answer and the same gap within 1e-9 R.
    ///
    /// Ignored: fails. The same GJK early stop leaves the gap of one order of the cones up to
    /// 2e-9 R off (pinned in `gjk_stops_early_on_a_repeated_support_point`).
    #[test]
    #[ignore = "engine: GJK stops on a repeated support point (see gjk_stops_early_on_a_repeated_support_point)"]
    fn swapping_the_stars_changes_nothing(
        q in prop::array::uniform3(0.0f64..1.0),
        dir in prop::array::uniform2(0.0f64..1.0),
        dist in 0.0f64..2.2,
    ) {
        let p = random_pose(q, dir, dist);
        let back = inverse(&p);
        let g = geometry();
        prop_assert_eq!(g.intersects(&p), g.intersects(&back), "{}", show(&p));
        let (c, cb) = (g.contact(&p), g.contact(&back));
        prop_assert_eq!(c.is_touching(), cb.is_touching(), "{}", show(&p));
        prop_assert!(
            (c.gap() - cb.gap()).abs() <= 1e-9 * R,
            "{} against {}: {}", c.gap(), cb.gap(), show(&p)
        );
    }

    /// Moving B along the engine's normal by the depth (and 1e-6 R) parts the stars.
    ///
    /// Ignored: fails. The depth is the deepest single part pair's, so other overlapping part
    /// pairs can hold the stars together (coincident centres: the cores' depth 0.6R, the spikes
    /// still crossing); and a cone pair whose GJK simplex is flat when it finds them touching
    /// reports depth 0 (coaxial spikes). Pinned in `moving_by_the_depth_parts_the_stars_pinned`.
    #[test]
    #[ignore = "engine: the depth is one part pair's (see moving_by_the_depth_parts_the_stars_pinned)"]
    fn moving_by_the_depth_parts_the_stars(
        q in prop::array::uniform3(0.0f64..1.0),
        dir in prop::array::uniform2(0.0f64..1.0),
        dist in 0.0f64..2.0,
    ) {
        let p = random_pose(q, dir, dist);
        let c = geometry().contact(&p);
        depth_parts(&p, &c).unwrap_or_else(|e| panic!("{e}"));
    }
}

/// A pose from a rotation's rows and a translation, as failures print them.
fn pose_from_rows(rows: [[f64; 3]; 3], t: [f64; 3]) -> Pose {
    Pose {
        rotation: DMat3::from_cols_array_2d(&rows).transpose(),
        translation: DVec3::from_array(t),
    }
}

/// Poses where the engine's cone-against-cone GJK stops on a repeated support point with a
/// negative proven lower bound and returns |v| as the distance (R = 0.2):
/// 1. A's -y tip against B's -z flank: the engine's gap 2.7307e-7, the judge's bracket
///    [1.99994e-7, 2.00001e-7];
/// 2. B's -y flank across A's +z tip: the engine says apart (gap 1.566e-8), the judge finds a
///    point of B's surface inside A (the stars overlap by some 1e-8);
/// 3. the same rotation, apart by 0.0318: the gap is right (within 4e-12) but the inverse pose's
///    is 4.0e-10 (2e-9 R) too large;
/// 4. a random pose: the gap 0.0260625079, the judge's bracket [0.02606250704, 0.02606250705]
///    (8.8e-10, 4.4e-9 R, too large);
/// 5. A's +y tip against B's core, B's spike nearer: the gap 0.00329765758, the judge's bracket
///    [0.00329765732, 0.00329765732] (2.6e-10, 1.3e-9 R, too large);
/// 6. found by `foveal-bench shape-check` (N = 10,000, seed 1, after 181 steps, its frame 180
///    counted from 0, pair 829-1020, the engine's own `shape_pose`): the engine says apart (gap
///    7.22e-8, the lower bound when GJK stops -1.45e-6) and the pair not colliding; the judge
///    finds them touching. The same pose rounded differently in its last bits gives the
///    engine's touching, depth 7.0e-8.
#[test]
#[ignore = "engine: GJK stops on a repeated support point with a negative lower bound"]
fn gjk_stops_early_on_a_repeated_support_point() {
    let turned = [
        [-0.4395201902019903, 0.7212404978859622, 0.535382243461638],
        [
            -0.06010972049037944,
            -0.6183205246486121,
            0.7836239852766342,
        ],
        [0.8962191829610522, 0.31223688604563615, 0.3151179193336189],
    ];
    let poses = [
        pose_from_rows(
            [
                [-0.4861875144221892, 0.6690934274903209, 0.5620815653525998],
                [-0.2572856508513036, 0.505105354007931, -0.823815923139717],
                [
                    -0.8351202276834128,
                    -0.5451445373859832,
                    -0.0734277786142794,
                ],
            ],
            [
                0.07388666481946009,
                -0.3227769532729873,
                0.0013066786054916901,
            ],
        ),
        pose_from_rows(
            turned,
            [
                0.07110722818620314,
                -0.06312304419186321,
                0.2554891580216273,
            ],
        ),
        pose_from_rows(
            turned,
            [
                0.062177638657492165,
                -0.059584390630514766,
                0.28659724695892097,
            ],
        ),
    ];
    let mut failures = Vec::new();
    for p in &poses {
        for q in [*p, inverse(p)] {
            let c = check(&q);
            failures.extend(c.answer.into_iter().chain(c.points).chain(c.gap));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// A pose where the engine's contact says touching (depth 0) and its `intersects` apart, and the
/// judge proves the stars 4.384e-4 (2.2e-3 R) apart (R = 0.2). Found by `foveal-bench
/// shape-check` (N = 10,000, seed 1, origin (1e7, -1e7, 5e6), after 61 steps, its frame 60
/// counted from 0, pair 3587-8914, the engine's own `shape_pose`): in `contact`'s GJK for one
/// cone pair a support point comes back one ulp from a vertex already in the simplex (so the
/// exact-equality test for a repeat misses it), the tetrahedron is flat, the origin is read as
/// enclosed, EPA fails on the flat simplex and the pair is reported touching at depth 0.
#[test]
fn gjk_reads_a_flat_simplex_as_enclosing() {
    let p = pose_from_rows(
        [
            [-0.12910998746488267, 0.7170201971654303, 0.6849909838776458],
            [-0.25852351546669583, 0.6425461288371003, -0.721318282221654],
            [
                -0.9573380819164976,
                -0.27021567159086823,
                0.10240745939206353,
            ],
        ],
        [
            -0.16341721966580094,
            0.04269004667950341,
            -0.061027046954944236,
        ],
    );
    check(&p).assert_all();
}

/// Inputs on which the `star_contact` fuzz target finds a contact normal that is not a unit
/// vector (|n| - 1 of 1.1e-7 to 2.1e-7), the rotation from the normalised quaternion (x, y, z, w)
/// of the first four numbers, the translation the next three wrapped into (-3R, 3R), R = 1:
/// 1. B's spike pointing at A's centre within 1e-9 of its length (core of A against that cone):
///    the radial part of the centre's offset is a difference of nearly equal numbers, its
///    rounding leaves an axial component of some 1e-7 in the unit radial direction, and the
///    slant normal built from it is 1.1e-7 too long;
/// 2. the same for another spike, 2.1e-7 too long;
/// 3. centres 2.3e-159 apart: the cores' normal divides the offset by its length, whose square
///    underflows, 1.6e-7 too long.
#[test]
fn contact_normals_are_unit_pinned() {
    let inputs: [[f64; 8]; 3] = [
        [
            8.579405861249677e-103,
            -1.8325506472120096e-6,
            -1.832550647205125e-6,
            2.9141991980873104e-307,
            4.3782472911551893e-305,
            2261634.5098050525,
            -4.656944807942254e-10,
            1.5810949027e-314,
        ],
        [
            3.3224550058474415e-223,
            -4.656612873077393e-10,
            -1.7881393450240894e-6,
            1.3552226809780377e-308,
            4.9806105157086026e54,
            -4.873462772862743e-10,
            1.5158994592271818e-30,
            1.5810948143e-314,
        ],
        [
            1.727235351802899e-77,
            0.0,
            1.1319601547336064e-72,
            3.0517578125e-5,
            7.2911220192911456e-304,
            2.276265936144519e-159,
            5.4685083952068926e-304,
            0.0,
        ],
    ];
    let mut failures = Vec::new();
    for v in inputs {
        let q = DQuat::from_xyzw(v[0], v[1], v[2], v[3]);
        let r = 10f64.powf(v[7].clamp(-6.0, 6.0));
        let pose = Pose {
            rotation: DMat3::from_quat(q / q.length()),
            translation: DVec3::new(v[4] % 3.0, v[5] % 3.0, v[6] % 3.0) * r,
        };
        let c = StarGeometry::new(Star::new(r)).contact(&pose);
        let n = c.normal().length();
        if (n - 1.0).abs() > 1e-9 {
            failures.push(format!("|n| = {n}: {c:?} at {pose:?}"));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// Poses where moving B along the engine's normal by the depth and 1e-6 R leaves the stars
/// touching (R = 0.2):
/// 1. coincident centres, B turned half a turn about y: depth 0.12 (the cores') along +x, the
///    spikes still cross;
/// 2. B turned half a turn about y, 1.25R up A's y axis: depth 0.00975 (A's tip in B's core)
///    along +y, while A's +y and B's -y spikes overlap coaxially (0.0375 to part them
///    sideways, 0.15 along the axis): their GJK ends touching on a flat simplex and reports
///    depth 0.
#[test]
#[ignore = "engine: the depth is one part pair's, and 0 for a flat GJK simplex"]
fn moving_by_the_depth_parts_the_stars_pinned() {
    let half_turn = [[-1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, -1.0]];
    let mut failures = Vec::new();
    for t in [[0.0, 0.0, 0.0], [0.0, 1.25 * R, 0.0]] {
        let p = pose_from_rows(half_turn, t);
        let c = geometry().contact(&p);
        if let Err(e) = depth_parts(&p, &c) {
            failures.push(e);
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// Seeded uniforms (splitmix64).
struct Uniforms(u64);

impl Uniforms {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }

    fn in_range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }

    fn two(&mut self) -> [f64; 2] {
        [self.next(), self.next()]
    }

    fn three(&mut self) -> [f64; 3] {
        [self.next(), self.next(), self.next()]
    }

    fn three_in(&mut self, h: f64) -> [f64; 3] {
        [
            self.in_range(-h, h),
            self.in_range(-h, h),
            self.in_range(-h, h),
        ]
    }

    fn index(&mut self, n: usize) -> usize {
        ((self.next() * n as f64) as usize).min(n - 1)
    }
}

/// What a sweep found: verdict counts, mean patch evaluations, wrong answers, gaps outside the
/// judge's bracket and closest points off the surfaces.
#[derive(Debug, Default)]
struct Swept {
    counts: [usize; 3],
    evaluations: f64,
    wrong: Vec<String>,
    gaps: Vec<String>,
    points: Vec<String>,
    /// Closest points off the surfaces, of pairs whose gap is in the bracket.
    points_alone: usize,
}

/// `cases` seeded poses drawn by `make`, each checked.
fn sweep(seed: u64, cases: usize, mut make: impl FnMut(&mut Uniforms, usize) -> Pose) -> Swept {
    let mut u = Uniforms(seed);
    let mut s = Swept::default();
    for i in 0..cases {
        let c = check(&make(&mut u, i));
        s.counts[c.judged.verdict as usize] += 1;
        s.evaluations += c.judged.evaluations as f64 / cases as f64;
        s.points_alone += usize::from(c.points.is_some() && c.gap.is_none());
        s.wrong.extend(c.answer);
        s.gaps.extend(c.gap);
        s.points.extend(c.points);
    }
    eprintln!(
        "{cases} poses (seed {seed:#x}): {} touching, {} apart, {} ambiguous; {} wrong answers, {} \
         gaps outside the bracket, {} closest points off the surfaces ({} with the gap in the \
         bracket); {:.0} patch evaluations a pose",
        s.counts[Verdict::Touching as usize],
        s.counts[Verdict::Apart as usize],
        s.counts[Verdict::Ambiguous as usize],
        s.wrong.len(),
        s.gaps.len(),
        s.points.len(),
        s.points_alone,
        s.evaluations
    );
    s
}

/// Random, tip-tip, tip-core and flank poses in turn.
fn mixed_pose(u: &mut Uniforms, i: usize) -> Pose {
    match i % 4 {
        0 => random_pose(u.three(), u.two(), u.in_range(0.0, 2.2)),
        1 => {
            let angle = u.in_range(-0.05, 0.05);
            tips_pose(
                u.index(6),
                u.index(6),
                u.three(),
                u.two(),
                angle,
                u.three_in(0.02),
            )
        }
        2 => tip_core_pose(
            u.index(6),
            u.three(),
            u.in_range(-0.06, 0.06),
            u.three_in(0.05),
        ),
        _ => {
            let (ka, kb, q) = (u.index(6), u.index(6), u.three());
            let (around, tilt) = (u.next(), u.in_range(-0.2, 0.2));
            let (a, b, slack) = (
                u.in_range(0.1, 0.9),
                u.in_range(0.1, 0.9),
                u.in_range(-0.1, 0.1),
            );
            flanks_pose(ka, kb, q, around, tilt, a, b, slack)
        }
    }
}

/// Seeded poses of every kind but grazing, counting the judge's verdicts (run with
/// `--nocapture` to see them): the engine agrees on every sure one, and few are ambiguous.
#[test]
fn a_seeded_sweep_agrees_and_counts_the_ambiguous() {
    let cases = 1_200;
    let s = sweep(0x5eed, cases, mixed_pose);
    assert!(s.wrong.is_empty(), "{}", s.wrong.join("\n"));
    assert!(
        s.counts[Verdict::Ambiguous as usize] * 100 <= cases,
        "{:?}",
        s.counts
    );
}

/// The same sweep's gaps and closest points: every proven-apart pair's gap within 1e-9 R of the
/// judge's bracket, its closest points on the surfaces.
///
/// Ignored: fails (21 of 1,200 poses, gaps up to 5e-8 R too large and, for 20 of them, a
/// closest point more than 1e-9 R inside its star) with the GJK early stop of
/// `gjk_stops_early_on_a_repeated_support_point`.
#[test]
#[ignore = "engine: GJK stops on a repeated support point (see gjk_stops_early_on_a_repeated_support_point)"]
fn a_seeded_sweep_has_the_judges_gaps() {
    let s = sweep(0x5eed, 1_200, mixed_pose);
    assert!(s.gaps.is_empty(), "{}", s.gaps.join("\n"));
    assert!(s.points.is_empty(), "{}", s.points.join("\n"));
}

/// Seeded grazing poses, 1e-6 R either side of the engine's own contact.
///
/// Ignored: fails, with the GJK early stop of `gjk_stops_early_on_a_repeated_support_point`.
#[test]
#[ignore = "engine: GJK stops on a repeated support point (see gjk_stops_early_on_a_repeated_support_point)"]
fn a_seeded_grazing_sweep_agrees() {
    let s = sweep(0x6a2e, 600, |u, _| {
        let base = random_pose(u.three(), u.two(), u.in_range(0.3, 2.2));
        grazing_pose(&base, if u.next() < 0.5 { -1e-6 } else { 1e-6 })
    });
    assert!(s.wrong.is_empty(), "{}", s.wrong.join("\n"));
    assert!(s.gaps.is_empty(), "{}", s.gaps.join("\n"));
    assert!(s.points.is_empty(), "{}", s.points.join("\n"));
}

/// B's pose in A's frame, from the bodies' world state, computed here (not by the engine's
/// `shape_pose`).
fn pair_pose(sim: &Simulation, a: usize, b: usize) -> Pose {
    let w = sim.world();
    let ma = DMat3::from_quat(w.orientation[a]);
    let mb = DMat3::from_quat(w.orientation[b]);
    Pose {
        rotation: ma.transpose() * mb,
        translation: ma.transpose() * (w.position[b] - w.position[a]),
    }
}

/// Every candidate pair of every frame of an exact run: the engine calls it colliding iff the
/// judge does not prove it apart, and the judge does not prove it touching unless colliding.
fn scene_agrees(origin: [f64; 3], frames: u32) -> [usize; 3] {
    let mut cfg = SimConfig::default();
    cfg.scene.bodies = 500;
    cfg.scene.origin = origin;
    cfg.budget = BudgetSpec::Exact;
    assert_eq!(cfg.scene.truth, Truth::Shape);
    let mut sim = Simulation::new(cfg).expect("valid");
    let o = Oracle::new(sim.config().scene.shape_radius);
    let mut counts = [0usize; 3];
    for frame in 0..frames {
        sim.step(None, &FrozenClock);
        assert_eq!(sim.pairs().len(), sim.candidate_pairs().len());
        for (p, &(a, b)) in sim.pairs().iter().zip(sim.candidate_pairs()) {
            assert_eq!((p.a, p.b), (a, b));
            let colliding = match p.status {
                PairStatus::Colliding => true,
                PairStatus::Separate => false,
                s => panic!("an exact frame left pair {a}-{b} {s:?}"),
            };
            let pose = pair_pose(&sim, a as usize, b as usize);
            let j = o.verdict(&placement(&pose));
            counts[j.verdict as usize] += 1;
            match j.verdict {
                Verdict::Touching => assert!(
                    colliding,
                    "frame {frame}, pair {a}-{b}: the judge finds them touching, the engine \
                     not colliding: {}",
                    show(&pose)
                ),
                Verdict::Apart => assert!(
                    !colliding,
                    "frame {frame}, pair {a}-{b}: the judge proves them {} apart, the engine \
                     colliding: {}",
                    j.lower,
                    show(&pose)
                ),
                Verdict::Ambiguous => {}
            }
        }
    }
    counts
}

#[test]
fn exact_scene_statuses_agree_with_the_judge() {
    let c = scene_agrees([0.0; 3], 30);
    eprintln!(
        "N = 500, 30 frames: {} touching, {} apart, {} ambiguous",
        c[0], c[1], c[2]
    );
    assert!(c[0] > 0 && c[1] > 0, "{c:?}");
}

#[test]
fn far_from_the_origin_the_statuses_agree_too() {
    let c = scene_agrees([1e7, -1e7, 5e6], 30);
    eprintln!(
        "N = 500 at origin 1e7, 30 frames: {} touching, {} apart, {} ambiguous",
        c[0], c[1], c[2]
    );
    assert!(c[0] > 0 && c[1] > 0, "{c:?}");
}
