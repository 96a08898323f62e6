//! The exact contact of two stars (`star_contact`) on arbitrary poses: a rotation from a
//! normalised quaternion, a translation wrapped into (-3R, 3R) per axis (values already inside are
//! kept exactly, so the fuzzer can reach exact tip-to-tip and grazing placements), R from 1e-6 to
//! 1e6. Never panic; `intersects` agrees with `contact`; every number of the contact is finite,
//! the depth and the gap are non-negative and the normal is a unit vector.
#![no_main]
use foveal_engine::shape::Star;
use foveal_engine::star_contact::{Contact, Pose, StarGeometry};
use glam::{DMat3, DQuat, DVec3};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|v: [f64; 8]| {
    if v.iter().any(|x| !x.is_finite()) {
        return;
    }
    let q = DQuat::from_xyzw(v[0], v[1], v[2], v[3]);
    let len = q.length();
    if !(len.is_finite() && len > 1e-6) {
        return;
    }
    let r = 10f64.powf(v[7].clamp(-6.0, 6.0));
    let t = DVec3::new(v[4] % 3.0, v[5] % 3.0, v[6] % 3.0) * r;
    let pose = Pose {
        rotation: DMat3::from_quat(q / len),
        translation: t,
    };
    let g = StarGeometry::new(Star::new(r));
    let hit = g.intersects(&pose);
    let c = g.contact(&pose);
    assert_eq!(
        hit,
        c.is_touching(),
        "{pose:?}: intersects {hit}, contact {c:?}"
    );
    let unit = |n: DVec3| (n.length() - 1.0).abs() <= 1e-9;
    match c {
        Contact::Touching {
            point,
            normal,
            depth,
        } => {
            assert!(
                point.is_finite() && normal.is_finite() && depth.is_finite(),
                "{pose:?}: {c:?}"
            );
            assert!(depth >= 0.0, "{pose:?}: {c:?}");
            assert!(unit(normal), "{pose:?}: {c:?}");
        }
        Contact::Apart {
            distance,
            point_a,
            point_b,
        } => {
            assert!(
                distance.is_finite() && point_a.is_finite() && point_b.is_finite(),
                "{pose:?}: {c:?}"
            );
            assert!(distance >= 0.0, "{pose:?}: {c:?}");
            assert!(unit(c.normal()), "{pose:?}: {c:?}");
        }
    }
    assert!(c.gap() >= 0.0 && c.gap().is_finite(), "{pose:?}: {c:?}");
});
