//! Tests against the real EyeLink recording in the repository's `data/gaze`: 66.8 s at 1000 Hz, left eye,
//! 1920x1080 px, the same samples as ASC and as pixel CSV, plus the tracker's fixation list.

use std::fs::File;
use std::io::BufReader;
use std::path::PathBuf;

use super::asc::AscReader;
use super::csv::{CsvFormat, CsvGazeReader};
use super::{Eye, GazeSample, ScreenPx};

const STEM: &str = "eyelink-1000hz-left";
/// Sample lines in both files.
const SAMPLES: usize = 66_827;
/// Samples with no position (blinks, track loss).
const MISSING: usize = 710;

fn data_path(extension: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../data/gaze")
        .join(format!("{STEM}.{extension}"))
}

fn open(extension: &str) -> BufReader<File> {
    let path = data_path(extension);
    let file = File::open(&path).unwrap_or_else(|e| panic!("open {}: {e}", path.display()));
    BufReader::new(file)
}

fn read_asc() -> Vec<GazeSample> {
    let mut reader = AscReader::new(open("asc"));
    let samples: Vec<_> = reader
        .by_ref()
        .collect::<Result<_, _>>()
        .expect("the ASC file parses");
    assert_eq!(
        reader.screen(),
        ScreenPx::new(1920.0, 1080.0),
        "DISPLAY_COORDS 0 0 1919 1079"
    );
    assert_eq!(reader.eye(), Eye::Left);
    samples
}

fn read_csv() -> Vec<GazeSample> {
    let mut reader = CsvGazeReader::new(open("samples.csv")).with_eye(Eye::Left);
    let samples: Vec<_> = reader
        .by_ref()
        .collect::<Result<_, _>>()
        .expect("the CSV file parses");
    assert_eq!(reader.format(), Some(CsvFormat::Pixels));
    assert_eq!(
        reader.screen(),
        ScreenPx::new(1920.0, 1080.0),
        "from the `# ... screen 1920x1080 px` comment"
    );
    samples
}

fn check_recording(samples: &[GazeSample], start_s: f64) {
    assert_eq!(samples.len(), SAMPLES);
    assert_eq!(samples[0].t_s, start_s);
    let duration = samples[SAMPLES - 1].t_s - samples[0].t_s;
    assert!((duration - 66.826).abs() < 1e-9, "66.8 s: {duration}");
    for pair in samples.windows(2) {
        let dt = pair[1].t_s - pair[0].t_s;
        assert!(dt >= 0.0, "time goes back at {:?}", pair[1]);
        assert!(
            (dt - 0.001).abs() < 1e-6,
            "1000 Hz, no gaps: {dt} at {:?}",
            pair[1]
        );
    }
    let missing = samples.iter().filter(|s| !s.is_valid()).count();
    assert_eq!(missing, MISSING);
    // About 1 % missing: a plausible amount of blinking for a minute of recording.
    let fraction = missing as f64 / SAMPLES as f64;
    assert!(
        (0.001..0.05).contains(&fraction),
        "fraction missing {fraction}"
    );
    for s in samples.iter().filter(|s| s.is_valid()) {
        assert!(
            (0.0..=1.0).contains(&s.x) && (0.0..=1.0).contains(&s.y),
            "on screen: {s:?}"
        );
        assert_eq!(s.validity, 1.0);
    }
    for s in samples.iter().filter(|s| !s.is_valid()) {
        assert_eq!((s.x, s.y, s.validity), (0.0, 0.0, 0.0));
    }
}

#[test]
fn asc_recording_parses() {
    let samples = read_asc();
    // ASC timestamps start at 1000 ms.
    check_recording(&samples, 1.0);
    let first = samples[0];
    assert_eq!(
        (first.x, first.y, first.eye),
        (742.1 / 1920.0, 552.2 / 1080.0, Eye::Left)
    );
}

#[test]
fn csv_recording_parses() {
    let samples = read_csv();
    check_recording(&samples, 0.0);
    assert!(
        samples.iter().all(|s| s.fixation.is_none()),
        "the CSV has no fixation flags"
    );
}

#[test]
fn asc_and_csv_give_the_same_samples() {
    let asc = read_asc();
    let csv = read_csv();
    assert_eq!(asc.len(), csv.len());
    for (a, c) in asc.iter().zip(&csv) {
        // Same clock up to the 1 s origin of the ASC file.
        assert!((a.t_s - 1.0 - c.t_s).abs() < 1e-9, "{a:?} vs {c:?}");
        assert_eq!(
            (a.x, a.y, a.validity, a.eye),
            (c.x, c.y, c.validity, c.eye),
            "at {}",
            c.t_s
        );
    }
}

#[test]
fn asc_fixation_flags_match_the_tracker_fixation_list() {
    // `eye,start_s,end_s,x_px,y_px`, times from the start of the recording.
    let text = std::fs::read_to_string(data_path("fixations.csv")).expect("fixation list");
    let fixations: Vec<(f64, f64)> = text
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("eye"))
        .map(|l| {
            let fields: Vec<f64> = l.split(',').map(|f| f.parse().expect("number")).collect();
            (fields[1], fields[2])
        })
        .collect();
    assert_eq!(fixations.len(), 21);
    let samples = read_asc();
    let first_event_s = fixations[0].0;
    let mut in_fixation = 0;
    for s in &samples {
        let t = s.t_s - 1.0;
        if t < first_event_s - 1e-9 {
            assert_eq!(s.fixation, None, "no event seen yet at {t}");
            continue;
        }
        let expected = fixations
            .iter()
            .any(|(start, end)| t > start - 1e-9 && t < end + 1e-9);
        assert_eq!(s.fixation, Some(expected), "at {t}");
        in_fixation += usize::from(expected);
    }
    // The recording is mostly one long fixation on the centre.
    assert!(in_fixation > SAMPLES * 9 / 10, "{in_fixation}");
}

/// The detector with its documented defaults against the tracker's own online parser, on the
/// whole recording (the target of docs/BENCHMARKS.md: F1 >= 0.9, median onset and offset
/// differences <= 10 ms).
#[test]
fn ivt_defaults_agree_with_the_tracker_parser() {
    use crate::agreement::{Interval, compare};
    use crate::detect::{DetectorParams, detect_all};
    use crate::geometry::ViewingGeometry;

    let reference: Vec<Interval> = crate::fixation_list::read(open("fixations.csv"))
        .expect("fixation list")
        .iter()
        .map(|f| Interval {
            start_s: f.start_s,
            end_s: f.end_s,
        })
        .collect();
    let samples = read_csv();
    let detected: Vec<Interval> = detect_all(
        DetectorParams::default(),
        ViewingGeometry::default(),
        &samples,
    )
    .iter()
    .map(|f| Interval {
        start_s: f.start_s,
        end_s: f.end_s,
    })
    .collect();
    let a = compare(&detected, &reference);
    // The two reference fixations shorter than the 60 ms minimum (36 and 40 ms) are missed;
    // everything detected matches.
    assert_eq!((a.detected, a.reference, a.matched), (19, 21, 19), "{a:?}");
    assert!(a.f1 >= 0.9, "{a:?}");
    assert!(a.onset.median_abs_s <= 0.010, "{a:?}");
    assert!(a.offset.median_abs_s <= 0.010, "{a:?}");
}
