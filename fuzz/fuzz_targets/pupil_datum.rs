//! Pupil Core msgpack payloads arriving over ZeroMQ (`foveal bridge pupil`): never panic, and a
//! datum that decodes maps to a sample whose validity is in [0, 1].
#![no_main]
use foveal_gaze::pupil::{DEFAULT_MIN_CONFIDENCE, decode_payload};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let (surface, payload) = match data.split_first() {
        Some((flag, rest)) => (flag & 1 == 1, rest),
        None => return,
    };
    if let Ok(gazes) = decode_payload(payload, "gaze.3d.01.", surface) {
        for gaze in gazes.into_iter().flatten() {
            let s = gaze.to_sample(DEFAULT_MIN_CONFIDENCE);
            assert!((0.0..=1.0).contains(&s.validity), "{s:?}");
        }
    }
});
