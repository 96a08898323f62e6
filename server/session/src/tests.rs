//! The format round-trips every float's bits, refuses damaged files naming the line, and the
//! replay finds a changed metric.

use foveal_engine::{BudgetSpec, Fixation, FrozenClock, SimConfig, Simulation};
use foveal_gaze::online::ProcessorConfig;

use super::*;

fn settings() -> ServerSettings {
    ServerSettings {
        frame_rate_hz: 60.0,
        gaze_max_age_s: 0.5,
        gaze_processing: GazeSettings::from(&ProcessorConfig::default()),
    }
}

fn small(budget: BudgetSpec) -> SimConfig {
    let mut c = SimConfig::default();
    c.scene.bodies = 120;
    c.budget = budget;
    c
}

/// A session of `frames` frames run directly on the engine, the fixation moving every frame.
fn recorded(config: &SimConfig, frames: u64) -> Vec<u8> {
    let mut sim = Simulation::new(config.clone()).expect("valid config");
    let mut w =
        SessionWriter::new(Vec::new(), &Header::new(config.clone(), settings())).expect("header");
    for i in 0..frames {
        let t = i as f64 / 60.0;
        let fixation = Fixation {
            x: 0.5 + 0.3 * (t * 2.0).sin(),
            y: 0.5 + 0.2 * (t * 3.0).cos(),
            age_s: t / 7.0,
            // A widened track now and then: the replay must hand the engine the same radius.
            uncertainty_deg: if i % 7 == 3 { 2.5 + t } else { 0.0 },
        };
        w.write(&Record::Gaze(GazeRecord {
            received_s: t,
            source: "stream:1".into(),
            tracker_time_s: t + 1e-3 / 3.0,
            x: Some(fixation.x),
            y: Some(fixation.y),
            validity: 1.0,
            eye: "left".into(),
            fixation: None,
        }))
        .expect("gaze");
        let report = sim.step(Some(fixation), &FrozenClock).clone();
        w.write(&Record::Frame(Box::new(FrameRecord {
            index: i,
            t_s: t + 1e-4,
            fixation,
            fixation_source: "gaze".into(),
            report,
        })))
        .expect("frame");
    }
    w.finish(0).expect("trailer").0
}

fn read(bytes: &[u8]) -> Result<Session, SessionError> {
    Session::read(bytes)
}

#[test]
fn awkward_floats_come_back_bit_for_bit() {
    let awkward = [
        0.1 + 0.2,
        1.0 / 3.0,
        std::f64::consts::PI,
        f64::MIN_POSITIVE / 3.0, // subnormal
        -0.0,
        f64::MAX,
        1e-300,
        0.123_456_789_012_345_68,
        2.0_f64.sqrt() * 1e17,
    ];
    let config = small(BudgetSpec::SphereTests(500));
    let mut w =
        SessionWriter::new(Vec::new(), &Header::new(config.clone(), settings())).expect("header");
    for (i, &v) in awkward.iter().enumerate() {
        let mut report = foveal_engine::FrameReport {
            index: i as u64,
            sim_time: v,
            geometric_inaccuracy: v,
            perceived_inaccuracy: Some(v),
            ..Default::default()
        };
        report.profile.narrow_ns = u64::MAX;
        w.write(&Record::Frame(Box::new(FrameRecord {
            index: i as u64,
            t_s: v,
            fixation: Fixation {
                x: v,
                y: -v,
                age_s: v.abs(),
                uncertainty_deg: v.abs(),
            },
            fixation_source: "gaze".into(),
            report,
        })))
        .expect("frame");
    }
    let bytes = w.finish(0).expect("trailer").0;
    let s = read(&bytes).expect("reads back");
    assert_eq!(s.frames.len(), awkward.len());
    for (f, &v) in s.frames.iter().zip(&awkward) {
        for got in [
            f.t_s,
            f.fixation.x,
            -f.fixation.y,
            f.report.sim_time,
            f.report.geometric_inaccuracy,
            f.report.perceived_inaccuracy.expect("some"),
        ] {
            assert_eq!(got.to_bits(), v.to_bits(), "{got:e} vs {v:e}");
        }
        assert_eq!(f.report.profile.narrow_ns, u64::MAX);
    }
    assert_eq!(s.header.sim, config);
}

#[test]
fn a_recorded_run_replays_bit_for_bit() {
    for budget in [
        BudgetSpec::SphereTests(600),
        BudgetSpec::FractionOfExact(0.2),
    ] {
        let config = small(budget);
        let s = read(&recorded(&config, 40)).expect("reads");
        assert_eq!((s.frames.len(), s.gaze.len()), (40, 40));
        let out = replay(&s).expect("replays");
        assert!(out.is_bit_for_bit(), "{budget:?}: {out:?}");
        assert_eq!(out.exact_frames, 40);
        // The budget bit: a replay that compared nothing would not notice.
        assert!(s.frames.iter().any(|f| f.report.deemed > 0), "{budget:?}");
    }
}

#[test]
fn replay_names_the_first_changed_metric() {
    let config = small(BudgetSpec::SphereTests(600));
    let mut s = read(&recorded(&config, 30)).expect("reads");
    let bumped = s.frames[17]
        .report
        .perceived_inaccuracy
        .map(|p| f64::from_bits(p.to_bits() + 1));
    s.frames[17].report.perceived_inaccuracy = bumped;
    s.frames[21].report.sphere_tests += 1;
    let out = replay(&s).expect("replays");
    let m = out.mismatch.expect("a one-ulp change is found");
    assert_eq!((m.frame, m.field), (17, "perceived_inaccuracy"));
    assert_eq!(out.frames, 18, "stops at the first difference");
    assert!(m.to_string().contains("frame 17"), "{m}");

    let mut s = read(&recorded(&config, 30)).expect("reads");
    s.frames[21].report.sphere_tests += 1;
    let m = replay(&s).expect("replays").mismatch.expect("found");
    assert_eq!((m.frame, m.field), (21, "sphere_tests"));
    // The timings are not compared: they are the machine's, not the engine's.
    let mut s = read(&recorded(&config, 30)).expect("reads");
    s.frames[3].report.profile.narrow_ns += 12_345;
    assert!(replay(&s).expect("replays").is_bit_for_bit());
}

#[test]
fn a_wall_clock_session_is_compared_only_where_it_is_deterministic() {
    let config = small(BudgetSpec::WallMs(0.05));
    let mut s = read(&recorded(&config, 10)).expect("reads");
    s.frames[4].report.sphere_tests += 1;
    let out = replay(&s).expect("replays");
    assert_eq!((out.wall_clock_frames, &out.mismatch), (10, &None));
    assert!(
        !out.is_bit_for_bit(),
        "a wall-clock replay never claims to be exact"
    );
    s.frames[4].fixation.x += 0.25;
    let m = replay(&s).expect("replays").mismatch.expect("found");
    assert_eq!((m.frame, m.field), (4, "fixation"));
}

#[test]
fn a_dropped_frame_stops_the_replay_at_the_gap() {
    let config = small(BudgetSpec::SphereTests(600));
    let mut s = read(&recorded(&config, 20)).expect("reads");
    s.frames.remove(12);
    let out = replay(&s).expect("replays");
    assert_eq!(
        (out.gap_at, out.frames, &out.mismatch),
        (Some(12), 12, &None)
    );
    assert!(!out.is_bit_for_bit());
}

#[test]
fn damaged_files_are_refused_naming_the_line() {
    let config = small(BudgetSpec::SphereTests(600));
    let good = recorded(&config, 5);
    let text = String::from_utf8(good.clone()).expect("utf-8");
    let line_of = |e: SessionError| match e {
        SessionError::Line { line, reason } => (line, reason),
        other => panic!("expected a line error, got {other}"),
    };
    // Cut in the middle of line 4 (the second frame is line 5: header, gaze, frame, gaze, ...).
    let lines: Vec<&str> = text.lines().collect();
    let cut: usize = lines[..3].iter().map(|l| l.len() + 1).sum::<usize>() + lines[3].len() / 2;
    let (line, reason) = line_of(read(&good[..cut]).expect_err("truncated mid-line"));
    assert_eq!(line, 4, "{reason}");
    // Cut at a line boundary: no trailer.
    let cut: usize = lines[..6].iter().map(|l| l.len() + 1).sum();
    let (line, reason) = line_of(read(&good[..cut]).expect_err("no trailer"));
    assert!(reason.contains("trailer"), "{reason}");
    assert_eq!(line, 6);
    // A corrupted field.
    let bad = text.replacen(
        "\"real_collisions\":",
        "\"real_collisions\":\"x\",\"y\":",
        1,
    );
    let (line, reason) = line_of(read(bad.as_bytes()).expect_err("corrupt"));
    assert_eq!(line, 3, "{reason}");
    // Another version.
    let bad = text.replacen("\"version\":1", "\"version\":99", 1);
    let (line, reason) = line_of(read(bad.as_bytes()).expect_err("version"));
    assert!(line == 1 && reason.contains("99"), "{reason}");
    // Frames out of order.
    let mut swapped = lines.clone();
    swapped.swap(2, 4);
    let (line, reason) = line_of(read(swapped.join("\n").as_bytes()).expect_err("order"));
    assert!(line == 5 && reason.contains("increase"), "{line}: {reason}");
    // An empty file.
    let (line, _) = line_of(read(b"").expect_err("empty"));
    assert_eq!(line, 1);
}
