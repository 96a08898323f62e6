//! One trial as the page sends it, checked against its session's design, and its row in the
//! results CSV.
//!
//! The CSV is plain: a header row of column names, one row per trial, commas, no quoting (every
//! text field is a plain name, checked here), numbers in degrees and milliseconds. R's
//! `read.csv`, pandas and PsychoPy's data tools read it as it is, and `foveal psych fit` reads
//! its `participant`, `eccentricity_deg`, `gap_deg`, `response` and `valid` columns.

use super::design::{Design, is_plain_name};
use super::fields::{FieldError, Fields};

/// The results CSV's columns, in order.
pub const COLUMNS: &[&str] = &[
    "participant",
    "session",
    "design",
    "trial",
    "block",
    "cell",
    "eccentricity_deg",
    "direction_deg",
    "gap_label",
    "gap_deg",
    "response",
    "correct",
    "response_source",
    "rt_ms",
    "valid",
    "invalid_reason",
    "repeat_of",
    "duration_ms",
    "intended_ms",
    "frames",
    "refresh_ms",
    "onset_ms",
    "gap_px",
    "x_px",
    "y_px",
    "frame_ms",
    "distractors",
    "axis_deg",
];

/// Most frame timestamps one trial may carry (a 2 s stimulus at 360 Hz is 720).
pub const MAX_FRAMES: usize = 1000;

/// One trial as the page posts it (JSON).
#[derive(Debug, Clone, PartialEq)]
pub struct TrialRecord {
    /// 1-based position in the session, repeats included: the next one the session expects.
    pub trial: u32,
    /// 1-based block.
    pub block: u32,
    /// The condition's index, as [`Design::cell`] numbers them: ((eccentricity index x
    /// directions + direction index) x gap levels + gap level index) x distractor levels plus
    /// the distractor level's index.
    pub cell: u32,
    /// Eccentricity of the point between the discs (degrees; one of the design's).
    pub eccentricity_deg: f64,
    /// Its direction from the fixation (degrees; one of the design's).
    pub direction_deg: f64,
    /// The gap level's label (one of the design's).
    pub gap_label: String,
    /// The gap (degrees; the level's).
    pub gap_deg: f64,
    /// `apart` or `touching`.
    pub response: String,
    /// `key` or `mouse`.
    pub response_source: String,
    /// From the stimulus's onset to the response (ms).
    pub rt_ms: f64,
    /// Whether the presentation's timing held (no dropped or late frame, the duration right).
    pub valid: bool,
    /// Why not (`late_frame`, `duration`, ...), empty when valid.
    pub invalid_reason: String,
    /// The trial this one repeats (an invalid one earlier in the block).
    pub repeat_of: Option<u32>,
    /// The stimulus's measured duration: from the frame that drew it to the frame that cleared
    /// it (ms, `requestAnimationFrame` timestamps).
    pub duration_ms: f64,
    /// The duration the design asks for (ms).
    pub intended_ms: f64,
    /// Frames the stimulus was drawn on.
    pub frames: u32,
    /// The display's refresh period measured before the block (ms).
    pub refresh_ms: f64,
    /// The onset from the session's start (ms).
    pub onset_ms: f64,
    /// The gap as drawn (device pixels).
    pub gap_px: f64,
    /// The point between the discs from the fixation (CSS pixels, right and up).
    pub x_px: f64,
    /// See `x_px`.
    pub y_px: f64,
    /// Every frame's timestamp from the onset's to the offset's (ms after the onset).
    pub frame_ms: Vec<f64>,
    /// Distractors shown (one of the design's levels; 0 without distractors).
    pub distractors: u32,
    /// The pair's axis as drawn, degrees counter-clockwise from the right (a `random` axis's
    /// draw; `None` where the design fixes the axis).
    pub axis_deg: Option<f64>,
}

/// A trial refused: the field and why.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("`{field}`: {why}")]
pub struct TrialError {
    /// The field.
    pub field: String,
    /// What it must be.
    pub why: String,
}

fn refuse(field: &str, why: impl Into<String>) -> TrialError {
    TrialError {
        field: field.to_owned(),
        why: why.into(),
    }
}

fn within(field: &str, v: f64, lo: f64, hi: f64) -> Result<(), TrialError> {
    if v.is_finite() && (lo..=hi).contains(&v) {
        Ok(())
    } else {
        Err(refuse(field, format!("{v} is not within {lo}..={hi}")))
    }
}

/// Whether two design values are the same level (they went through JSON and back).
fn same(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * a.abs().max(1.0)
}

impl TrialRecord {
    /// The trial in a JSON body, every field read by name.
    pub fn from_json(bytes: &[u8]) -> Result<Self, FieldError> {
        const NUM: &str = "a number";
        const COUNT: &str = "a whole number >= 0";
        let mut f = Fields::parse(bytes)?;
        let t = Self {
            trial: f.req("trial", COUNT)?,
            block: f.req("block", COUNT)?,
            cell: f.req("cell", COUNT)?,
            eccentricity_deg: f.req("eccentricity_deg", NUM)?,
            direction_deg: f.req("direction_deg", NUM)?,
            gap_label: f.req("gap_label", "a string")?,
            gap_deg: f.req("gap_deg", NUM)?,
            response: f.req("response", "`apart` or `touching`")?,
            response_source: f.req("response_source", "`key` or `mouse`")?,
            rt_ms: f.req("rt_ms", NUM)?,
            valid: f.req("valid", "true or false")?,
            invalid_reason: f.opt("invalid_reason", "a string")?.unwrap_or_default(),
            repeat_of: f.opt("repeat_of", COUNT)?,
            duration_ms: f.req("duration_ms", NUM)?,
            intended_ms: f.req("intended_ms", NUM)?,
            frames: f.req("frames", COUNT)?,
            refresh_ms: f.req("refresh_ms", NUM)?,
            onset_ms: f.req("onset_ms", NUM)?,
            gap_px: f.req("gap_px", NUM)?,
            x_px: f.req("x_px", NUM)?,
            y_px: f.req("y_px", NUM)?,
            frame_ms: f.req("frame_ms", "an array of numbers")?,
            distractors: f.opt("distractors", COUNT)?.unwrap_or(0),
            axis_deg: f.opt("axis_deg", NUM)?,
        };
        f.done()?;
        Ok(t)
    }

    /// Check every field, the conditions against `design`; `expected` is the trial number the
    /// session waits for.
    pub fn validate(&self, design: &Design, expected: u32) -> Result<(), TrialError> {
        if self.trial != expected {
            return Err(refuse(
                "trial",
                format!(
                    "{} is not the next trial of this session: expected {expected}{}",
                    self.trial,
                    if self.trial < expected {
                        " (that trial is already stored)"
                    } else {
                        ""
                    }
                ),
            ));
        }
        if !(1..=design.blocks).contains(&self.block) {
            return Err(refuse(
                "block",
                format!("{} is not within 1..={}", self.block, design.blocks),
            ));
        }
        within("eccentricity_deg", self.eccentricity_deg, 0.0, 180.0)?;
        let Some(e) = design
            .eccentricities_deg
            .iter()
            .position(|&e| same(e, self.eccentricity_deg))
        else {
            return Err(refuse(
                "eccentricity_deg",
                format!(
                    "{} is not one of the design's {:?}",
                    self.eccentricity_deg, design.eccentricities_deg
                ),
            ));
        };
        within("direction_deg", self.direction_deg, 0.0, 360.0)?;
        let Some(d) = design
            .directions_deg
            .iter()
            .position(|&d| same(d, self.direction_deg))
        else {
            return Err(refuse(
                "direction_deg",
                format!(
                    "{} is not one of the design's {:?}",
                    self.direction_deg, design.directions_deg
                ),
            ));
        };
        let Some(g) = design.gaps.iter().position(|g| g.label == self.gap_label) else {
            let labels: Vec<_> = design.gaps.iter().map(|g| g.label.as_str()).collect();
            return Err(refuse(
                "gap_label",
                format!(
                    "{:?} is not one of the design's {labels:?}",
                    self.gap_label.chars().take(40).collect::<String>()
                ),
            ));
        };
        let level = &design.gaps[g];
        let Some(l) = (0..design.distractor_levels())
            .find(|&l| design.distractor_count(l) == self.distractors)
        else {
            let counts: Vec<u32> = (0..design.distractor_levels())
                .map(|l| design.distractor_count(l))
                .collect();
            return Err(refuse(
                "distractors",
                format!(
                    "{} is not one of the design's levels {counts:?}",
                    self.distractors
                ),
            ));
        };
        match (self.axis_deg, design.stimulus.pair_axis.as_str()) {
            (Some(a), _) => within("axis_deg", a, 0.0, 360.0)?,
            (None, "random") => {
                return Err(refuse(
                    "axis_deg",
                    "is required: the design draws the pair's axis per trial",
                ));
            }
            (None, _) => {}
        }
        let cell = design.cell(e, d, g, l);
        if self.cell as usize != cell {
            return Err(refuse(
                "cell",
                format!("{} is not the cell of these conditions ({cell})", self.cell),
            ));
        }
        if !(self.gap_deg.is_finite() && same(level.gap_deg, self.gap_deg)) {
            return Err(refuse(
                "gap_deg",
                format!(
                    "{} is not the `{}` level's {}",
                    self.gap_deg, level.label, level.gap_deg
                ),
            ));
        }
        if !matches!(self.response.as_str(), "apart" | "touching") {
            return Err(refuse("response", "must be `apart` or `touching`"));
        }
        if !matches!(self.response_source.as_str(), "key" | "mouse") {
            return Err(refuse("response_source", "must be `key` or `mouse`"));
        }
        within("rt_ms", self.rt_ms, 0.0, 3_600_000.0)?;
        if self.valid != self.invalid_reason.is_empty() {
            return Err(refuse(
                "invalid_reason",
                "must be empty for a valid trial and name the fault of an invalid one",
            ));
        }
        if !self.invalid_reason.is_empty() && !is_plain_name(&self.invalid_reason, 32) {
            return Err(refuse(
                "invalid_reason",
                "must be 1 to 32 ASCII letters, digits, `-` or `_`",
            ));
        }
        if let Some(r) = self.repeat_of
            && !(1..self.trial).contains(&r)
        {
            return Err(refuse(
                "repeat_of",
                format!("{r} is not an earlier trial (1..{})", self.trial),
            ));
        }
        within("duration_ms", self.duration_ms, 0.0, 60_000.0)?;
        within("intended_ms", self.intended_ms, 0.0, 60_000.0)?;
        if !same(self.intended_ms, design.stimulus.duration_ms) {
            return Err(refuse(
                "intended_ms",
                format!(
                    "{} is not the design's {}",
                    self.intended_ms, design.stimulus.duration_ms
                ),
            ));
        }
        if self.frames as usize > MAX_FRAMES {
            return Err(refuse(
                "frames",
                format!("{} is above {MAX_FRAMES}", self.frames),
            ));
        }
        within("refresh_ms", self.refresh_ms, 0.5, 1000.0)?;
        within("onset_ms", self.onset_ms, 0.0, 1e9)?;
        within("gap_px", self.gap_px, 0.0, 1e5)?;
        within("x_px", self.x_px, -1e5, 1e5)?;
        within("y_px", self.y_px, -1e5, 1e5)?;
        if self.frame_ms.len() > MAX_FRAMES {
            return Err(refuse(
                "frame_ms",
                format!("{} timestamps; at most {MAX_FRAMES}", self.frame_ms.len()),
            ));
        }
        for (i, &t) in self.frame_ms.iter().enumerate() {
            within(&format!("frame_ms[{i}]"), t, 0.0, 60_000.0)?;
        }
        Ok(())
    }

    /// The trial's CSV row (newline included), in [`COLUMNS`]' order.
    pub fn row(&self, participant: &str, session: &str, design: &str) -> String {
        let correct = (self.response == "apart") == (self.gap_deg > 0.0);
        let frames: Vec<String> = self.frame_ms.iter().map(|t| format!("{t:.3}")).collect();
        let fields = [
            participant.to_owned(),
            session.to_owned(),
            design.to_owned(),
            self.trial.to_string(),
            self.block.to_string(),
            self.cell.to_string(),
            self.eccentricity_deg.to_string(),
            self.direction_deg.to_string(),
            self.gap_label.clone(),
            self.gap_deg.to_string(),
            self.response.clone(),
            u8::from(correct).to_string(),
            self.response_source.clone(),
            format!("{:.1}", self.rt_ms),
            u8::from(self.valid).to_string(),
            self.invalid_reason.clone(),
            self.repeat_of.map_or_else(String::new, |r| r.to_string()),
            format!("{:.3}", self.duration_ms),
            self.intended_ms.to_string(),
            self.frames.to_string(),
            format!("{:.3}", self.refresh_ms),
            format!("{:.1}", self.onset_ms),
            format!("{:.3}", self.gap_px),
            format!("{:.2}", self.x_px),
            format!("{:.2}", self.y_px),
            // `;` inside the field: the file stays one comma per column.
            frames.join(";"),
            self.distractors.to_string(),
            self.axis_deg
                .map_or_else(String::new, |a| format!("{a:.3}")),
        ];
        let mut line = fields.join(",");
        line.push('\n');
        line
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::psych::design::{DEFAULT_DESIGN, Designs};

    pub(crate) fn record() -> TrialRecord {
        TrialRecord {
            trial: 1,
            block: 1,
            cell: 16,
            eccentricity_deg: 5.0,
            direction_deg: 90.0,
            gap_label: "small".into(),
            gap_deg: 0.05,
            response: "apart".into(),
            response_source: "key".into(),
            rt_ms: 512.3,
            valid: true,
            invalid_reason: String::new(),
            repeat_of: None,
            duration_ms: 150.2,
            intended_ms: 150.0,
            frames: 9,
            refresh_ms: 16.68,
            onset_ms: 2000.0,
            gap_px: 2.2,
            x_px: 0.0,
            y_px: 217.0,
            frame_ms: vec![0.0, 16.7, 33.3],
            distractors: 0,
            axis_deg: None,
        }
    }

    #[test]
    fn a_row_has_every_column_and_no_stray_comma() {
        let row = record().row("p01", "1", DEFAULT_DESIGN);
        assert_eq!(row.trim_end().split(',').count(), COLUMNS.len());
        assert!(
            row.starts_with("p01,1,experiment1,1,1,16,5,90,small,0.05,apart,1,key,512.3,1,,,"),
            "{row}"
        );
        assert!(row.trim_end().ends_with("0.000;16.700;33.300,0,"), "{row}");
    }

    /// Experiment 4's trials name their distractor level and the axis drawn; the cell counts
    /// the level, and a count or axis the design does not hold is refused by field.
    #[test]
    fn distractor_levels_and_drawn_axes_are_checked() {
        let design = Designs::default().load("experiment4").expect("design");
        let counts = design
            .distractors
            .as_ref()
            .expect("distractors")
            .counts
            .clone();
        let e = design
            .eccentricities_deg
            .iter()
            .position(|&x| x == 5.0)
            .expect("5 degrees");
        let d = design
            .directions_deg
            .iter()
            .position(|&x| x == 90.0)
            .expect("90 degrees");
        let g = design
            .gaps
            .iter()
            .position(|x| x.label == "small")
            .expect("small");
        let mut r = TrialRecord {
            distractors: counts[2],
            axis_deg: Some(37.5),
            cell: design.cell(e, d, g, 2) as u32,
            intended_ms: design.stimulus.duration_ms,
            gap_deg: design.gaps[g].gap_deg,
            ..record()
        };
        assert_eq!(r.validate(&design, 1), Ok(()));
        let row = r.row("p01", "1", "experiment4");
        assert!(
            row.trim_end().ends_with(&format!(",{},37.500", counts[2])),
            "{row}"
        );
        r.cell = design.cell(e, d, g, 1) as u32;
        assert_eq!(r.validate(&design, 1).expect_err("cell").field, "cell");
        r.cell = design.cell(e, d, g, 2) as u32;
        r.distractors = 999;
        assert_eq!(
            r.validate(&design, 1).expect_err("count").field,
            "distractors"
        );
        r.distractors = counts[2];
        r.axis_deg = None;
        assert_eq!(r.validate(&design, 1).expect_err("axis").field, "axis_deg");
        r.axis_deg = Some(f64::NAN);
        assert_eq!(r.validate(&design, 1).expect_err("nan").field, "axis_deg");
    }

    #[test]
    fn conditions_outside_the_design_are_refused_by_field() {
        let design = Designs::default().load(DEFAULT_DESIGN).expect("design");
        assert_eq!(record().validate(&design, 1), Ok(()));
        let mut r = record();
        r.gap_deg = 0.06;
        assert_eq!(
            record().validate(&design, 2).expect_err("order").field,
            "trial"
        );
        assert_eq!(r.validate(&design, 1).expect_err("gap").field, "gap_deg");
        let mut r = record();
        r.eccentricity_deg = f64::NAN;
        assert_eq!(
            r.validate(&design, 1).expect_err("nan").field,
            "eccentricity_deg"
        );
        let mut r = record();
        r.valid = false;
        assert_eq!(
            r.validate(&design, 1).expect_err("reason").field,
            "invalid_reason"
        );
        r.invalid_reason = "late,frame".into();
        assert_eq!(
            r.validate(&design, 1).expect_err("comma").field,
            "invalid_reason"
        );
        let mut r = record();
        r.frame_ms = vec![0.0; MAX_FRAMES + 1];
        assert_eq!(
            r.validate(&design, 1).expect_err("frames").field,
            "frame_ms"
        );
    }
}
