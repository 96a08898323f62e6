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
use crate::gaze::agreement::{Agreement, Interval, compare_groups};
use crate::gaze::asc::AscReader;
use crate::gaze::csv::CsvGazeReader;
use crate::gaze::detect::{Detector, DetectorParams, FixationEvent};
use crate::gaze::fixation_list::{self, HEADER, ListedFixation, eye_code};
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
    /// Agreement with the reference list, if one was given: pooled over the eyes, each eye's
    /// detections matched only against the same eye's reference fixations.
    pub agreement: Option<Agreement>,
    /// With more than one eye scored, each eye's own agreement, by list code (0 left, 1 right).
    pub per_eye: Vec<(u8, Agreement)>,
    /// Runs of samples whose timestamps went back before an earlier sample of the same eye: the
    /// detector cannot use them (it treats them as missing), so the caller says so.
    pub backwards: Vec<BackwardsBlock>,
}

/// A run of consecutive samples of one eye stamped earlier than a sample before them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BackwardsBlock {
    /// The eye's list code (0 left, 1 right, 2 both or unknown).
    pub eye: u8,
    /// Samples in the run.
    pub samples: u64,
    /// Time of the run's first sample, seconds from the recording's first sample.
    pub first_s: f64,
    /// The latest time seen before the run, which its samples are earlier than, same origin.
    pub latest_s: f64,
}

/// The name of an eye's list code, for messages.
fn eye_name(code: u8) -> &'static str {
    match code {
        0 => "left",
        1 => "right",
        _ => "both/unknown",
    }
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

/// What [`detect`] found: the fixations, the eyes it ran on and the runs of backwards samples.
struct Detection {
    events: Vec<FixationEvent>,
    /// List codes of the eyes a detector ran on, in order of appearance.
    eyes: Vec<u8>,
    backwards: Vec<BackwardsBlock>,
}

/// Runs one detector per eye present (one in all, unless the eyes are given apart), and notes
/// the runs of samples stamped before an earlier sample of their eye (times relative to
/// `origin_s`).
fn detect(options: &FixationOptions, samples: &[GazeSample], origin_s: f64) -> Detection {
    struct PerEye {
        eye: Eye,
        detector: Detector,
        latest_s: f64,
        /// Index in `backwards` of the run the previous sample was part of.
        open_run: Option<usize>,
    }
    let mut eyes: Vec<PerEye> = Vec::new();
    let mut events = Vec::new();
    let mut backwards: Vec<BackwardsBlock> = Vec::new();
    for s in samples {
        let index = match eyes.iter().position(|e| e.eye == s.eye) {
            Some(i) => i,
            None => {
                eyes.push(PerEye {
                    eye: s.eye,
                    detector: Detector::new(options.detector, options.geometry),
                    latest_s: f64::NEG_INFINITY,
                    open_run: None,
                });
                eyes.len() - 1
            }
        };
        let per_eye = &mut eyes[index];
        if s.t_s < per_eye.latest_s {
            match per_eye.open_run {
                Some(run) => backwards[run].samples += 1,
                None => {
                    per_eye.open_run = Some(backwards.len());
                    backwards.push(BackwardsBlock {
                        eye: eye_code(s.eye),
                        samples: 1,
                        first_s: s.t_s - origin_s,
                        latest_s: per_eye.latest_s - origin_s,
                    });
                }
            }
        } else {
            per_eye.open_run = None;
            per_eye.latest_s = s.t_s;
        }
        events.extend(per_eye.detector.push(s).finished);
    }
    for e in &mut eyes {
        events.extend(e.detector.finish());
    }
    events.sort_by(|a, b| a.start_s.total_cmp(&b.start_s));
    let mut codes: Vec<u8> = Vec::new();
    for e in &eyes {
        let code = eye_code(e.eye);
        if !codes.contains(&code) {
            codes.push(code);
        }
    }
    Detection {
        events,
        eyes: codes,
        backwards,
    }
}

/// The reference fixations a detection on eye `eye` (list code) is scored against: the same
/// eye's. A reference that does not say the eye (all code 2) serves any eye, and a reference of
/// one eye only serves a detection on the mean of the eyes; anything else would let one eye's
/// detection match the other eye's fixation, so it is refused, naming what the list holds.
fn reference_for(eye: u8, reference: &[ListedFixation]) -> Result<Vec<Interval>, String> {
    let mut listed: Vec<u8> = reference.iter().map(|f| f.eye).collect();
    listed.sort_unstable();
    listed.dedup();
    let keep = |code: u8| -> Vec<Interval> {
        reference
            .iter()
            .filter(|f| f.eye == code)
            .map(|f| Interval {
                start_s: f.start_s,
                end_s: f.end_s,
            })
            .collect()
    };
    let holds = || {
        listed
            .iter()
            .map(|&c| {
                let n = reference.iter().filter(|f| f.eye == c).count();
                format!("{n} of eye {c} ({})", eye_name(c))
            })
            .collect::<Vec<_>>()
            .join(", ")
    };
    if listed.contains(&eye) {
        return Ok(keep(eye));
    }
    match (eye, listed.as_slice()) {
        (_, []) => Ok(Vec::new()),
        (0 | 1, [2]) => Ok(keep(2)),
        (2, [only]) => Ok(keep(*only)),
        (2, _) => Err(format!(
            "the detection ran on the mean of both eyes (eye 2) but the reference lists each eye \
             apart ({}): score one eye with --eyes left or right, or each with --eyes both",
            holds()
        )),
        (_, _) => Err(format!(
            "the reference lists no fixation of the {} eye (eye {eye}); it holds {}",
            eye_name(eye),
            holds()
        )),
    }
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
    let detection = detect(options, &samples, origin_s);
    report.backwards = detection.backwards;
    report.fixations = detection
        .events
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
        let (agreement, per_eye) =
            score(&report.fixations, &detection.eyes, &listed).map_err(|reason| {
                ClientError::InvalidOption {
                    name: "--compare",
                    reason: format!("{}: {reason}", reference.display()),
                }
            })?;
        report.agreement = Some(agreement);
        report.per_eye = per_eye;
    }
    Ok(report)
}

/// Scores `detected` (found on the eyes `eyes`, list codes) against `reference` eye by eye (see
/// [`reference_for`]): the pooled agreement, and each eye's own when there are several.
///
/// # Errors
/// A reference that cannot be matched to the detected eyes, saying why.
pub fn score(
    detected: &[ListedFixation],
    eyes: &[u8],
    reference: &[ListedFixation],
) -> Result<(Agreement, Vec<(u8, Agreement)>), String> {
    let mut groups = Vec::new();
    for &eye in eyes {
        let found: Vec<Interval> = detected
            .iter()
            .filter(|f| f.eye == eye)
            .map(|f| Interval {
                start_s: f.start_s,
                end_s: f.end_s,
            })
            .collect();
        groups.push((eye, found, reference_for(eye, reference)?));
    }
    let per_eye = if groups.len() > 1 {
        groups
            .iter()
            .map(|(eye, d, r)| (*eye, compare_groups(&[(d, r)])))
            .collect()
    } else {
        Vec::new()
    };
    let pooled: Vec<(&[Interval], &[Interval])> = groups
        .iter()
        .map(|(_, d, r)| (d.as_slice(), r.as_slice()))
        .collect();
    Ok((compare_groups(&pooled), per_eye))
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
    for (eye, a) in &report.per_eye {
        writeln!(
            out,
            "# {} eye: detected {}, reference {}, matched {}, precision {:.3}, recall {:.3}, F1 {:.3}",
            eye_name(*eye),
            a.detected,
            a.reference,
            a.matched,
            a.precision,
            a.recall,
            a.f1
        )?;
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

#[cfg(test)]
mod tests {
    use super::*;

    fn fix(eye: u8, start_s: f64, end_s: f64) -> ListedFixation {
        ListedFixation {
            eye,
            start_s,
            end_s,
            x_px: 0.0,
            y_px: 0.0,
        }
    }

    #[test]
    fn each_eye_is_scored_against_its_own_reference_only() {
        // The left eye's detection lies on the right eye's reference fixation and vice versa.
        let detected = [fix(0, 0.0, 1.0), fix(1, 2.0, 3.0)];
        let reference = [fix(0, 2.0, 3.0), fix(1, 0.0, 1.0)];
        let (pooled, per_eye) = score(&detected, &[0, 1], &reference).expect("scores");
        assert_eq!(
            (pooled.detected, pooled.reference, pooled.matched),
            (2, 2, 0)
        );
        assert_eq!(per_eye.len(), 2);
        assert!(
            per_eye
                .iter()
                .all(|(_, a)| a.matched == 0 && a.reference == 1)
        );
        // One eye: scored against that eye's reference fixations only.
        let (left, per_eye) = score(&detected[..1], &[0], &reference).expect("scores");
        assert_eq!((left.detected, left.reference, left.matched), (1, 1, 0));
        assert!(per_eye.is_empty());
        let matching = [fix(0, 0.1, 0.9), fix(1, 5.0, 6.0), fix(1, 7.0, 8.0)];
        let (left, _) = score(&detected[..1], &[0], &matching).expect("scores");
        assert_eq!((left.reference, left.matched, left.f1), (1, 1, 1.0));
    }

    #[test]
    fn references_without_eyes_serve_any_eye_and_mismatches_are_refused() {
        let detected = [fix(0, 0.0, 1.0)];
        let unknown = [fix(2, 0.0, 1.0)];
        let (a, _) = score(&detected, &[0], &unknown).expect("an eye-less reference");
        assert_eq!(a.matched, 1);
        let right_only = [fix(1, 0.0, 1.0)];
        let err = score(&detected, &[0], &right_only).expect_err("no left-eye reference");
        assert!(err.contains("no fixation of the left eye"), "{err}");
        // The mean of both eyes against a reference of one eye is scored; against both, refused.
        let mean = [fix(2, 0.0, 1.0)];
        let (a, _) = score(&mean, &[2], &right_only).expect("one-eyed reference");
        assert_eq!(a.matched, 1);
        let both = [fix(0, 0.0, 1.0), fix(1, 0.0, 1.0)];
        let err = score(&mean, &[2], &both).expect_err("eyes listed apart");
        assert!(err.contains("--eyes left or right"), "{err}");
    }
}
