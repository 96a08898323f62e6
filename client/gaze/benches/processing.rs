//! Cost per sample of the server's online gaze processing: validation, the 1€ filter and the
//! fixation detector (I-VT and I-DT), on the scripted viewer's samples at 1 kHz and 2 kHz (short
//! fixations) and on the EyeLink recording in `data/gaze` at 1 kHz (fixations of up to 11 s).
//! Target: at most 1 µs per sample (docs/BENCHMARKS.md).
//!
//! `cargo bench -p foveal-gaze --bench processing`

use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use foveal_gaze::detect::{DetectorParams, IdtParams, IvtParams};
use foveal_gaze::filter::OneEuroParams;
use foveal_gaze::online::{GazeProcessor, ProcessorConfig};
use foveal_gaze::validate::Validator;
use foveal_gaze::viewer::Viewer;
use foveal_gaze::{Eye, GazeSample};

/// Ten seconds of the scripted viewer at `rate_hz`, with a 150 ms blink every 3 s.
fn samples(rate_hz: f64) -> Vec<GazeSample> {
    let mut viewer = Viewer::new(11);
    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
    let n = (10.0 * rate_hz) as u32;
    (0..n)
        .map(|i| {
            let t = f64::from(i) / rate_hz;
            if t % 3.0 > 2.85 {
                return GazeSample::missing(t, Eye::Left);
            }
            let g = viewer.at(t);
            GazeSample::valid(t, g.x, g.y, Eye::Left)
        })
        .collect()
}

/// The EyeLink recording in the repository's `data/gaze` (66.8 s at 1 kHz).
fn recording() -> Vec<GazeSample> {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../data/gaze/eyelink-1000hz-left.samples.csv");
    let file =
        std::fs::File::open(&path).unwrap_or_else(|e| panic!("open {}: {e}", path.display()));
    foveal_gaze::csv::CsvGazeReader::new(std::io::BufReader::new(file))
        .collect::<Result<Vec<_>, _>>()
        .unwrap_or_else(|e| panic!("parse {}: {e}", path.display()))
}

fn bench(c: &mut Criterion) {
    let inputs = vec![
        ("viewer_1000hz", samples(1000.0)),
        ("viewer_2000hz", samples(2000.0)),
        ("eyelink_1000hz", recording()),
    ];
    for (input_name, input) in inputs {
        let mut group = c.benchmark_group(input_name);
        group.throughput(Throughput::Elements(input.len() as u64));
        for (name, detector) in [
            ("ivt", DetectorParams::Ivt(IvtParams::default())),
            ("idt", DetectorParams::Idt(IdtParams::default())),
        ] {
            let config = ProcessorConfig {
                filter: Some(OneEuroParams::default()),
                detector: Some(detector),
                ..ProcessorConfig::default()
            };
            group.bench_function(format!("validate_filter_{name}"), |b| {
                b.iter(|| {
                    let mut validator = Validator::new();
                    let mut processor = GazeProcessor::new(config);
                    for s in &input {
                        let s = black_box(s);
                        // Missing samples reach the processor too: they mark track loss.
                        if validator.check(s).is_ok() || !s.is_valid() {
                            processor.push(s, s.t_s);
                        }
                    }
                    black_box(processor.state(10.0))
                });
            });
        }
        group.finish();
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
