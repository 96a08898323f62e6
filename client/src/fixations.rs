//! `foveal fixations`: runs the online fixation detector over a recording and lists the
//! fixations, optionally scored against a reference list.
//!
//! The detector is the same causal one the server runs, fed one sample at a time, so what this
//! prints is what the server would have scheduled around. Times are seconds from the recording's
//! first sample (an EyeLink ASC file's clock starts wherever the tracker's did), which is how
//! reference lists exported from a recording are usually written.

use std::fs::File;
use std::io::{BufReader, Read, Write};
use std::path::Path;

use crate::ClientError;
use crate::gaze::agreement::{Agreement, Interval, compare};
use crate::gaze::asc::AscReader;
use crate::gaze::csv::CsvGazeReader;
use crate::gaze::detect::{Detector, DetectorParams, FixationEvent};
use crate::gaze::fixation_list::{self, HEADER, ListedFixation};
use crate::gaze::geometry::ViewingGeometry;
use crate::gaze::{Binocular, Eye, GazeSample, ParseError, ScreenPx};
use crate::source::{RecordingFormat, detect_format};

/// What `foveal fixations` runs.
#[derive(Debug, Clone)]
pub struct FixationOptions {
    /// Detector and thresholds.
    pub detector: DetectorParams,
    /// Display geometry (degrees of visual angle).
    pub geometry: ViewingGeometry,
    /// Screen for pixel gaze and for the output's pixel positions; else the recording's own.
    pub screen: Option<ScreenPx>,
    /// How a binocular recording's eyes are used ([`Binocular::Both`]: each eye detected apart).
    pub eyes: Binocular,
}

/// What came of a run.
#[derive(Debug, Clone, Default)]
pub struct FixationReport {
    /// Samples read (valid or missing).
    pub samples: u64,
    /// Of them, missing (validity 0).
    pub missing: u64,
    /// Lines that did not parse (each reported on stderr by the caller, with its line number).
    pub bad_lines: Vec<String>,
    /// Fixations found, in order (per eye with [`Binocular::Both`]).
    pub fixations: Vec<ListedFixation>,
    /// Agreement with the reference list, if one was given.
    pub agreement: Option<Agreement>,
}

/// Reads every sample of a recording (CSV or ASC, from its extension or content).
fn read_samples(
    path: &Path,
    options: &FixationOptions,
    report: &mut FixationReport,
) -> Result<(Vec<GazeSample>, Option<ScreenPx>), ClientError> {
    let open = |what: &str| {
        File::open(path).map_err(|e| ClientError::io(format!("{what} {}", path.display()), e))
    };
    let mut head = Vec::new();
    open("open")?
        .take(16 * 1024)
        .read_to_end(&mut head)
        .map_err(|e| ClientError::io(format!("read {}", path.display()), e))?;
    let reader = BufReader::new(open("open")?);
    let mut samples = Vec::new();
    let mut keep = |r: Result<GazeSample, ParseError>, report: &mut FixationReport| match r {
        Ok(s) => {
            report.samples += 1;
            report.missing += u64::from(!s.is_valid());
            samples.push(s);
        }
        Err(e) => report.bad_lines.push(e.to_string()),
    };
    let screen = match detect_format(Some(path), &head) {
        RecordingFormat::Csv => {
            let mut r = CsvGazeReader::new(reader).with_binocular(options.eyes);
            if let Some(s) = options.screen {
                r = r.with_screen(s);
            }
            for item in r.by_ref() {
                keep(item, report);
            }
            r.screen()
        }
        RecordingFormat::Asc => {
            let mut r = AscReader::new(reader).with_binocular(options.eyes);
            if let Some(s) = options.screen {
                r = r.with_screen(s);
            }
            for item in r.by_ref() {
                keep(item, report);
            }
            r.screen()
        }
    };
    Ok((samples, screen))
}

/// Runs one detector per eye present (one in all, unless the eyes are given apart).
fn detect(options: &FixationOptions, samples: &[GazeSample]) -> Vec<FixationEvent> {
    let mut detectors: Vec<(Eye, Detector)> = Vec::new();
    let mut events = Vec::new();
    for s in samples {
        let index = match detectors.iter().position(|(eye, _)| *eye == s.eye) {
            Some(i) => i,
            None => {
                detectors.push((s.eye, Detector::new(options.detector, options.geometry)));
                detectors.len() - 1
            }
        };
        events.extend(detectors[index].1.push(s).finished);
    }
    for (_, d) in &mut detectors {
        events.extend(d.finish());
    }
    events.sort_by(|a, b| a.start_s.total_cmp(&b.start_s));
    events
}

/// Runs the detector over the recording at `path`; with `reference`, scores the result against
/// that fixation list.
///
/// # Errors
/// A file that cannot be read, a reference list that does not parse, a recording with no
/// sample or in pixels with no known screen.
pub fn run(
    path: &Path,
    reference: Option<&Path>,
    options: &FixationOptions,
) -> Result<FixationReport, ClientError> {
    let mut report = FixationReport::default();
    let (samples, screen) = read_samples(path, options, &mut report)?;
    let Some(origin_s) = samples.first().map(|s| s.t_s) else {
        return Err(ClientError::InvalidOption {
            name: "FILE",
            reason: format!(
                "{} has no gaze sample ({} lines did not parse{})",
                path.display(),
                report.bad_lines.len(),
                report
                    .bad_lines
                    .first()
                    .map(|e| format!(", the first: {e}"))
                    .unwrap_or_default()
            ),
        });
    };
    // Normalised recordings have no pixels: report on a unit "screen" then.
    let screen = screen
        .or(ScreenPx::new(1.0, 1.0))
        .ok_or_else(|| ClientError::InvalidOption {
            name: "screen",
            reason: "no screen size".into(),
        })?;
    report.fixations = detect(options, &samples)
        .iter()
        .map(|e| ListedFixation::from_event(e, screen, origin_s))
        .collect();
    if let Some(reference) = reference {
        let file = File::open(reference)
            .map_err(|e| ClientError::io(format!("open {}", reference.display()), e))?;
        let listed =
            fixation_list::read(BufReader::new(file)).map_err(|e| ClientError::InvalidOption {
                name: "--compare",
                reason: format!("{}: {e}", reference.display()),
            })?;
        let as_intervals = |list: &[ListedFixation]| -> Vec<Interval> {
            list.iter()
                .map(|f| Interval {
                    start_s: f.start_s,
                    end_s: f.end_s,
                })
                .collect()
        };
        report.agreement = Some(compare(
            &as_intervals(&report.fixations),
            &as_intervals(&listed),
        ));
    }
    Ok(report)
}

/// Writes the fixations as CSV ([`HEADER`]), then the agreement, if any, as `#` comment lines so
/// that the output still reads back as a fixation list.
///
/// # Errors
/// The first error of `out`.
pub fn write_report<W: Write>(mut out: W, report: &FixationReport) -> std::io::Result<()> {
    writeln!(out, "{HEADER}")?;
    for f in &report.fixations {
        writeln!(out, "{}", f.to_line())?;
    }
    if let Some(a) = &report.agreement {
        let ms = |s: f64| s * 1000.0;
        writeln!(
            out,
            "# agreement: detected {}, reference {}, matched {}",
            a.detected, a.reference, a.matched
        )?;
        writeln!(
            out,
            "# precision {:.3}, recall {:.3}, F1 {:.3}",
            a.precision, a.recall, a.f1
        )?;
        writeln!(
            out,
            "# onset difference (detected - reference): median |d| {:.1} ms, p90 |d| {:.1} ms, median d {:+.1} ms",
            ms(a.onset.median_abs_s),
            ms(a.onset.p90_abs_s),
            ms(a.onset.median_signed_s)
        )?;
        writeln!(
            out,
            "# offset difference (detected - reference): median |d| {:.1} ms, p90 |d| {:.1} ms, median d {:+.1} ms",
            ms(a.offset.median_abs_s),
            ms(a.offset.p90_abs_s),
            ms(a.offset.median_signed_s)
        )?;
    }
    out.flush()
}
