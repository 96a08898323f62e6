//! `foveal fixations`: the server's online detector over a recording, printed as CSV.

use std::io;
use std::path::PathBuf;

use super::{CommandError, Outcome};
use crate::fixations::{self, FixationOptions};
use crate::gaze::detect::{DetectorParams, IdtParams, IvtParams};
use crate::gaze::geometry::ViewingGeometry;
use crate::gaze::{Binocular, ScreenPx};

/// A fixation detector.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Detector {
    /// Velocity threshold (I-VT).
    Ivt,
    /// Dispersion threshold (I-DT).
    Idt,
}

/// What `foveal fixations` is asked for; a parameter left `None` keeps its default.
#[derive(Debug, Clone, PartialEq)]
pub struct FixationsCommand {
    /// The recording.
    pub file: PathBuf,
    /// A reference fixation list to score against.
    pub compare: Option<PathBuf>,
    /// The detector.
    pub detector: Detector,
    /// I-VT velocity threshold, degrees per second.
    pub velocity_threshold: Option<f64>,
    /// I-DT dispersion threshold, degrees.
    pub dispersion: Option<f64>,
    /// Shortest fixation, milliseconds.
    pub min_duration_ms: Option<f64>,
    /// The eyes of a binocular recording.
    pub eyes: Binocular,
    /// Physical screen size, width and height in cm.
    pub screen_cm: Option<(f64, f64)>,
    /// Eye to screen distance, cm.
    pub distance_cm: Option<f64>,
    /// Screen size for pixel gaze.
    pub screen: Option<ScreenPx>,
}

impl FixationsCommand {
    /// The detector's parameters, checked.
    ///
    /// # Errors
    /// [`CommandError::Usage`] for the other detector's threshold or a parameter that is not
    /// finite and positive.
    pub fn detector(&self) -> Result<DetectorParams, CommandError> {
        let mut detector = match self.detector {
            Detector::Ivt => DetectorParams::Ivt(IvtParams::default()),
            Detector::Idt => DetectorParams::Idt(IdtParams::default()),
        };
        match &mut detector {
            DetectorParams::Ivt(p) => {
                if self.dispersion.is_some() {
                    return Err(CommandError::Usage(
                        "--dispersion is an I-DT threshold: use it with --detector idt".into(),
                    ));
                }
                p.velocity_threshold_deg_s = self
                    .velocity_threshold
                    .unwrap_or(p.velocity_threshold_deg_s);
                p.min_duration_s = self
                    .min_duration_ms
                    .map_or(p.min_duration_s, |ms| ms / 1000.0);
            }
            DetectorParams::Idt(p) => {
                if self.velocity_threshold.is_some() {
                    return Err(CommandError::Usage(
                        "--velocity-threshold is an I-VT threshold: use it with --detector ivt"
                            .into(),
                    ));
                }
                p.max_dispersion_deg = self.dispersion.unwrap_or(p.max_dispersion_deg);
                p.min_duration_s = self
                    .min_duration_ms
                    .map_or(p.min_duration_s, |ms| ms / 1000.0);
            }
        }
        if let Err(name) = detector.validate() {
            return Err(CommandError::Usage(format!(
                "detector parameter `{name}` must be finite and positive"
            )));
        }
        Ok(detector)
    }

    /// The viewing geometry, checked.
    ///
    /// # Errors
    /// [`CommandError::Geometry`] for a size or distance that is not finite and positive.
    pub fn geometry(&self) -> Result<ViewingGeometry, CommandError> {
        let mut geometry = ViewingGeometry::default();
        if let Some((w, h)) = self.screen_cm {
            (geometry.width_cm, geometry.height_cm) = (w, h);
        }
        geometry.distance_cm = self.distance_cm.unwrap_or(geometry.distance_cm);
        geometry.validate().map_err(CommandError::Geometry)?;
        Ok(geometry)
    }
}

/// Detects the fixations of the recording and prints them as CSV to stdout (with the scores
/// against the reference as `#` lines); what was skipped or dropped, and the counts, go to
/// stderr.
///
/// # Errors
/// Parameters that cannot work, a file that cannot be read, stdout that cannot be written.
pub fn fixations(command: &FixationsCommand) -> Result<Outcome, CommandError> {
    let options = FixationOptions {
        detector: command.detector()?,
        geometry: command.geometry()?,
        screen: command.screen,
        eyes: command.eyes,
    };
    let report = fixations::run(&command.file, command.compare.as_deref(), &options)?;
    for line in report.bad_lines.iter().take(10) {
        eprintln!("skipped: {line}");
    }
    for b in &report.backwards {
        eprintln!(
            "dropped: {} sample(s) of eye {} from t = {:.4} s go back before t = {:.4} s, an \
             earlier sample's time; the detector treats them as missing",
            b.samples, b.eye, b.first_s, b.latest_s
        );
    }
    eprintln!(
        "{} samples ({} missing), {} lines skipped, {} fixations",
        report.samples,
        report.missing,
        report.bad_lines.len(),
        report.fixations.len()
    );
    fixations::write_report(io::stdout().lock(), &report).map_err(CommandError::WriteStdout)?;
    Ok(Outcome::Success)
}
