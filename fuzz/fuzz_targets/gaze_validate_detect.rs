//! Arbitrary sample streams through the server's path: validation, then the online processor with
//! a filter and each detector. Never panic; whatever steers is finite.
#![no_main]
use foveal_gaze::detect::{DetectorParams, IdtParams, IvtParams};
use foveal_gaze::filter::OneEuroParams;
use foveal_gaze::online::{GazeProcessor, ProcessorConfig};
use foveal_gaze::validate::{RejectKind, Validator};
use foveal_gaze::{Eye, GazeSample};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let samples: Vec<GazeSample> = data
        .chunks_exact(29)
        .map(|c| {
            let f = |i: usize| f64::from_le_bytes(c[i..i + 8].try_into().expect("8 bytes"));
            let eye = match c[28] % 4 {
                0 => Eye::Left,
                1 => Eye::Right,
                2 => Eye::Binocular,
                _ => Eye::Unspecified,
            };
            GazeSample {
                t_s: f(0),
                x: f(8),
                y: f(16),
                validity: f32::from_le_bytes(c[24..28].try_into().expect("4 bytes")),
                eye,
                fixation: None,
            }
        })
        .collect();
    for detector in [
        DetectorParams::Ivt(IvtParams::default()),
        DetectorParams::Idt(IdtParams::default()),
    ] {
        let mut validator = Validator::new();
        let mut processor = GazeProcessor::new(ProcessorConfig {
            filter: Some(OneEuroParams::default()),
            detector: Some(detector),
            ..ProcessorConfig::default()
        });
        for (i, s) in samples.iter().enumerate() {
            let usable = match validator.check(s) {
                Ok(()) => true,
                Err(r) => r.kind == RejectKind::Missing,
            };
            if usable {
                processor.push(s, i as f64 * 0.001);
            }
            let state = processor.state(i as f64 * 0.001);
            if let Some(p) = state.steer {
                assert!(p.x.is_finite() && p.y.is_finite(), "{state:?}");
            }
            assert!(state.widen_deg.is_finite());
        }
    }
});
