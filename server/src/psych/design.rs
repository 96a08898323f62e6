//! An experiment's design: conditions, levels, repetitions and timing, read from a JSON file so
//! that a lab changes them without code (`data/psych/experiment1.json` is the default; the
//! paper's experiments 2-4, with motion and distractors, are `experiment2` to `experiment4`; all
//! are embedded in the binary, and `--psych-designs DIR` adds the lab's own, `DIR/NAME.json`).
//!
//! A design is checked before any participant sees it: every field has a range, and a design out
//! of range, or with a field this version does not know, is refused with the field's path and its
//! limit, so that a typo never silently runs a different experiment.

use std::path::Path;

use serde::{Deserialize, Serialize};

/// The designs shipped in the binary, by name.
const EMBEDDED: &[(&str, &str)] = &[
    (
        "experiment1",
        include_str!(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../data/psych/experiment1.json"
        )),
    ),
    (
        "experiment2",
        include_str!(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../data/psych/experiment2.json"
        )),
    ),
    (
        "experiment3",
        include_str!(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../data/psych/experiment3.json"
        )),
    ),
    (
        "experiment4",
        include_str!(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../data/psych/experiment4.json"
        )),
    ),
];

/// The design `/psych` runs when the address names none.
pub const DEFAULT_DESIGN: &str = "experiment1";

/// Most trials a design may hold (practice excluded): about eight hours at 2.5 s a trial.
pub const MAX_TRIALS: usize = 10_000;

/// One experiment.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Design {
    /// Its name: what `/psych?design=NAME` selects and results files record.
    pub name: String,
    /// What the participant is told the experiment is.
    pub title: String,
    /// The two discs.
    pub stimulus: Stimulus,
    /// Arm length of the fixation cross (degrees).
    pub fixation_cross_deg: f64,
    /// From a response to the next stimulus's onset (ms).
    pub inter_stimulus_ms: f64,
    /// Eccentricities of the point between the discs from the fixation (degrees).
    pub eccentricities_deg: Vec<f64>,
    /// Directions of that point from the fixation (degrees, counter-clockwise from the right).
    pub directions_deg: Vec<f64>,
    /// Gap levels (a gap of 0 is the touching condition).
    pub gaps: Vec<GapLevel>,
    /// Times each cell (eccentricity x direction x gap, times the gap's weight) is shown.
    pub repetitions: u32,
    /// Blocks the trials are split into, with a break between two.
    pub blocks: u32,
    /// Practice trials before the first block (drawn from the cells, with feedback, not stored).
    pub practice_trials: u32,
    /// Which keys and mouse buttons answer what.
    pub responses: Responses,
    /// What makes a presentation's timing invalid.
    pub timing: Timing,
    /// Discs moving about the screen beside the pair (experiments 3 and 4), their number a
    /// factor crossed with the cells; none when absent.
    #[serde(default)]
    pub distractors: Option<Distractors>,
    /// Hide the fixation cross while the stimulus is shown (experiment 4, where a collision may
    /// happen at the fixation).
    #[serde(default)]
    pub hide_cross_during_stimulus: bool,
}

/// Distractors: discs of the pair's size moving in straight lines at a constant speed, from
/// random places within a circle about the fixation, in random directions (drawn per trial).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Distractors {
    /// Their number, one level per entry (the paper's three levels); 0 is allowed.
    pub counts: Vec<u32>,
    /// `red` (a pop-out search, experiment 3) or `white`, the pair's colour (a serial search,
    /// experiment 4).
    pub colour: String,
    /// Their speed (degrees per second).
    pub speed_deg_s: f64,
    /// The radius of the circle they start in, about the fixation (degrees).
    pub field_deg: f64,
}

/// The stimulus: two white discs on black, side by side along an axis.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Stimulus {
    /// Each disc's diameter (degrees).
    pub disc_diameter_deg: f64,
    /// How long the discs are shown (ms; rounded to whole frames by the display).
    pub duration_ms: f64,
    /// The line the two discs' centres lie on: `horizontal`, `vertical`, `radial` (through the
    /// fixation), `tangential` (across that line) or `random` (drawn per trial, as experiments 3
    /// and 4 randomise the direction of motion; the trial records the angle).
    pub pair_axis: String,
    /// Motion (experiments 2-4): each disc moves along the pair's axis at this speed (degrees
    /// per second), toward the other for the first half of the presentation and away for the
    /// second, closest (touching, or the gap) at its middle. Absent or 0: stationary.
    #[serde(default)]
    pub motion_speed_deg_s: Option<f64>,
}

/// A gap level.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GapLevel {
    /// Its name in the results (`touching`, `small`, ...).
    pub label: String,
    /// The gap between the discs' facing edges (degrees; 0: touching).
    pub gap_deg: f64,
    /// Copies of this level in each cell (2 for touching beside two gap levels gives half the
    /// trials touching).
    #[serde(default = "one")]
    pub weight: u32,
}

fn one() -> u32 {
    1
}

/// The two answers.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Responses {
    /// "The discs touch".
    pub touching: Answer,
    /// "There is a gap".
    pub apart: Answer,
}

/// How one answer is given.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Answer {
    /// Keys (`KeyboardEvent.key` values, e.g. `f`, `ArrowLeft`).
    pub keys: Vec<String>,
    /// Mouse button (`MouseEvent.button`: 0 left, 1 middle, 2 right), if any.
    #[serde(default)]
    pub mouse_button: Option<u8>,
}

/// When a presentation does not count.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Timing {
    /// A frame interval during the stimulus longer than this many refresh periods is a dropped
    /// or late frame: the trial is marked invalid and repeated at the end of its block.
    pub late_frame_factor: f64,
    /// Most repeats one block may add; beyond them an invalid trial is stored, not repeated.
    pub max_repeats_per_block: u32,
}

/// Why a design was refused: the field (a path such as `gaps[1].gap_deg`) and what it must be.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum DesignError {
    /// A field is out of range.
    #[error("design `{design}`: `{field}` = {value}: {expected}")]
    Field {
        /// The design's name (or file).
        design: String,
        /// The field's path.
        field: String,
        /// What it held.
        value: String,
        /// Its limit.
        expected: String,
    },
    /// The text is not a design (JSON syntax, a missing or unknown field, a wrong type).
    #[error("design `{design}`: {reason}")]
    Parse {
        /// The design's name (or file).
        design: String,
        /// serde's message: names the field, line and column.
        reason: String,
    },
    /// No design of that name.
    #[error("no design `{name}`: {known}")]
    Unknown {
        /// The name asked for.
        name: String,
        /// Where designs come from.
        known: String,
    },
    /// The design file could not be read.
    #[error("design `{name}`: reading {path}: {reason}")]
    Read {
        /// The name asked for.
        name: String,
        /// The file.
        path: String,
        /// The I/O error.
        reason: String,
    },
}

/// Whether `s` may name a design, a participant or a session: 1 to `max` ASCII letters, digits,
/// `-` and `_` (a file name on every system, and a CSV field that needs no quoting).
pub fn is_plain_name(s: &str, max: usize) -> bool {
    !s.is_empty()
        && s.len() <= max
        && s.bytes()
            .all(|b| b.is_ascii_alphanumeric() || b == b'-' || b == b'_')
}

/// Longest design name, gap label or key.
const MAX_NAME: usize = 32;

impl Design {
    /// The design in `text` (`design` names it in errors), checked.
    pub fn parse(design: &str, text: &str) -> Result<Self, DesignError> {
        let parsed: Self = serde_json::from_str(text).map_err(|e| DesignError::Parse {
            design: design.to_owned(),
            reason: e.to_string(),
        })?;
        parsed.validate()?;
        Ok(parsed)
    }

    /// Trials of the main blocks, repeats excluded.
    pub fn trials(&self) -> usize {
        let per_location: usize = self.gaps.iter().map(|g| g.weight as usize).sum();
        self.eccentricities_deg.len()
            * self.directions_deg.len()
            * per_location
            * self.distractor_levels()
            * self.repetitions as usize
    }

    /// The distractor levels crossed with the cells (1 without distractors).
    pub fn distractor_levels(&self) -> usize {
        self.distractors.as_ref().map_or(1, |d| d.counts.len())
    }

    /// The distractor count of level `l` (0 without distractors).
    pub fn distractor_count(&self, l: usize) -> u32 {
        self.distractors
            .as_ref()
            .and_then(|d| d.counts.get(l).copied())
            .unwrap_or(0)
    }

    /// The index of the cell of eccentricity `e`, direction `d`, gap level `g` and distractor
    /// level `l` (indices into the design's lists): the `cell` column. Without distractors (one
    /// level) it is experiment 1's numbering.
    pub fn cell(&self, e: usize, d: usize, g: usize, l: usize) -> usize {
        ((e * self.directions_deg.len() + d) * self.gaps.len() + g) * self.distractor_levels() + l
    }

    /// Check every field; the error names the first out of range.
    pub fn validate(&self) -> Result<(), DesignError> {
        let bad = |field: &str, value: String, expected: &str| DesignError::Field {
            design: self.name.chars().take(MAX_NAME).collect(),
            field: field.to_owned(),
            value,
            expected: expected.to_owned(),
        };
        let range = |field: &str, v: f64, lo: f64, hi: f64, unit: &str| {
            if v.is_finite() && (lo..=hi).contains(&v) {
                Ok(())
            } else {
                Err(bad(
                    field,
                    v.to_string(),
                    &format!("must be within {lo}..={hi} {unit}"),
                ))
            }
        };
        let count = |field: &str, n: usize, lo: usize, hi: usize| {
            if (lo..=hi).contains(&n) {
                Ok(())
            } else {
                Err(bad(
                    field,
                    format!("{n} entries"),
                    &format!("must have {lo} to {hi} entries"),
                ))
            }
        };
        if !is_plain_name(&self.name, MAX_NAME) {
            return Err(bad(
                "name",
                format!("{:?}", self.name.chars().take(40).collect::<String>()),
                "must be 1 to 32 ASCII letters, digits, `-` or `_`",
            ));
        }
        if self.title.chars().count() > 200 {
            return Err(bad(
                "title",
                format!("{} characters", self.title.chars().count()),
                "must be at most 200 characters",
            ));
        }
        range(
            "stimulus.disc_diameter_deg",
            self.stimulus.disc_diameter_deg,
            0.05,
            10.0,
            "degrees",
        )?;
        range(
            "stimulus.duration_ms",
            self.stimulus.duration_ms,
            10.0,
            2000.0,
            "ms",
        )?;
        if !matches!(
            self.stimulus.pair_axis.as_str(),
            "horizontal" | "vertical" | "radial" | "tangential" | "random"
        ) {
            return Err(bad(
                "stimulus.pair_axis",
                format!(
                    "{:?}",
                    self.stimulus.pair_axis.chars().take(40).collect::<String>()
                ),
                "must be `horizontal`, `vertical`, `radial`, `tangential` or `random`",
            ));
        }
        if let Some(v) = self.stimulus.motion_speed_deg_s {
            range(
                "stimulus.motion_speed_deg_s",
                v,
                0.0,
                100.0,
                "degrees per second",
            )?;
        }
        if let Some(d) = &self.distractors {
            count("distractors.counts", d.counts.len(), 1, 8)?;
            for (i, &n) in d.counts.iter().enumerate() {
                if n > 50 {
                    return Err(bad(
                        &format!("distractors.counts[{i}]"),
                        n.to_string(),
                        "must be within 0..=50",
                    ));
                }
                if d.counts[..i].contains(&n) {
                    return Err(bad(
                        &format!("distractors.counts[{i}]"),
                        n.to_string(),
                        "must differ from every other level",
                    ));
                }
            }
            if !matches!(d.colour.as_str(), "red" | "white") {
                return Err(bad(
                    "distractors.colour",
                    format!("{:?}", d.colour.chars().take(40).collect::<String>()),
                    "must be `red` (pop-out) or `white` (the pair's colour)",
                ));
            }
            range(
                "distractors.speed_deg_s",
                d.speed_deg_s,
                0.0,
                100.0,
                "degrees per second",
            )?;
            range("distractors.field_deg", d.field_deg, 0.5, 40.0, "degrees")?;
        }
        range(
            "fixation_cross_deg",
            self.fixation_cross_deg,
            0.1,
            5.0,
            "degrees",
        )?;
        range(
            "inter_stimulus_ms",
            self.inter_stimulus_ms,
            0.0,
            60_000.0,
            "ms",
        )?;
        count("eccentricities_deg", self.eccentricities_deg.len(), 1, 16)?;
        for (i, &e) in self.eccentricities_deg.iter().enumerate() {
            range(&format!("eccentricities_deg[{i}]"), e, 0.0, 40.0, "degrees")?;
        }
        count("directions_deg", self.directions_deg.len(), 1, 16)?;
        for (i, &d) in self.directions_deg.iter().enumerate() {
            if !(d.is_finite() && (0.0..360.0).contains(&d)) {
                return Err(bad(
                    &format!("directions_deg[{i}]"),
                    d.to_string(),
                    "must be within 0..360 degrees",
                ));
            }
        }
        count("gaps", self.gaps.len(), 1, 8)?;
        for (i, g) in self.gaps.iter().enumerate() {
            if !is_plain_name(&g.label, MAX_NAME) {
                return Err(bad(
                    &format!("gaps[{i}].label"),
                    format!("{:?}", g.label.chars().take(40).collect::<String>()),
                    "must be 1 to 32 ASCII letters, digits, `-` or `_`",
                ));
            }
            if self.gaps[..i].iter().any(|o| o.label == g.label) {
                return Err(bad(
                    &format!("gaps[{i}].label"),
                    g.label.clone(),
                    "must differ from every other level's label",
                ));
            }
            range(
                &format!("gaps[{i}].gap_deg"),
                g.gap_deg,
                0.0,
                5.0,
                "degrees",
            )?;
            if !(1..=16).contains(&g.weight) {
                return Err(bad(
                    &format!("gaps[{i}].weight"),
                    g.weight.to_string(),
                    "must be within 1..=16",
                ));
            }
        }
        if !(1..=100).contains(&self.repetitions) {
            return Err(bad(
                "repetitions",
                self.repetitions.to_string(),
                "must be within 1..=100",
            ));
        }
        let trials = self.trials();
        if trials > MAX_TRIALS {
            return Err(bad(
                "repetitions",
                self.repetitions.to_string(),
                &format!("the design would hold {trials} trials; at most {MAX_TRIALS}"),
            ));
        }
        if !(1..=50).contains(&self.blocks) || self.blocks as usize > trials {
            return Err(bad(
                "blocks",
                self.blocks.to_string(),
                &format!("must be within 1..=50 and at most the trials ({trials})"),
            ));
        }
        if self.practice_trials > 100 {
            return Err(bad(
                "practice_trials",
                self.practice_trials.to_string(),
                "must be within 0..=100",
            ));
        }
        let mut keys: Vec<&str> = Vec::new();
        for (name, answer) in [
            ("touching", &self.responses.touching),
            ("apart", &self.responses.apart),
        ] {
            count(&format!("responses.{name}.keys"), answer.keys.len(), 1, 4)?;
            for (i, k) in answer.keys.iter().enumerate() {
                let field = format!("responses.{name}.keys[{i}]");
                if k.is_empty() || k.chars().count() > 16 || k.chars().any(char::is_control) {
                    return Err(bad(
                        &field,
                        format!("{k:?}"),
                        "must be a key name of 1 to 16 characters",
                    ));
                }
                if k == " " {
                    return Err(bad(
                        &field,
                        format!("{k:?}"),
                        "must not be the space bar, which starts blocks",
                    ));
                }
                if keys.contains(&k.as_str()) {
                    return Err(bad(&field, format!("{k:?}"), "must answer one thing only"));
                }
                keys.push(k);
            }
            if let Some(b) = answer.mouse_button
                && b > 4
            {
                return Err(bad(
                    &format!("responses.{name}.mouse_button"),
                    b.to_string(),
                    "must be within 0..=4",
                ));
            }
        }
        if self.responses.touching.mouse_button.is_some()
            && self.responses.touching.mouse_button == self.responses.apart.mouse_button
        {
            return Err(bad(
                "responses.apart.mouse_button",
                format!("{:?}", self.responses.apart.mouse_button),
                "must differ from responses.touching.mouse_button",
            ));
        }
        range(
            "timing.late_frame_factor",
            self.timing.late_frame_factor,
            1.1,
            3.0,
            "refresh periods",
        )?;
        if self.timing.max_repeats_per_block > 1000 {
            return Err(bad(
                "timing.max_repeats_per_block",
                self.timing.max_repeats_per_block.to_string(),
                "must be within 0..=1000",
            ));
        }
        Ok(())
    }
}

/// Where designs come from: the lab's directory first (if given), then the embedded ones.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Designs {
    /// `--psych-designs DIR`.
    pub dir: Option<std::path::PathBuf>,
}

/// Largest design file read (a design is a page of JSON).
const MAX_DESIGN_BYTES: u64 = 64 * 1024;

impl Designs {
    /// The design called `name`, read and checked now (a lab may edit its file between sessions).
    pub fn load(&self, name: &str) -> Result<Design, DesignError> {
        if !is_plain_name(name, MAX_NAME) {
            return Err(DesignError::Unknown {
                name: name.chars().take(40).collect(),
                known: "a design name is 1 to 32 ASCII letters, digits, `-` or `_`".into(),
            });
        }
        if let Some(dir) = &self.dir {
            let path = dir.join(format!("{name}.json"));
            if path.is_file() {
                return read(name, &path);
            }
        }
        let Some((_, text)) = EMBEDDED.iter().find(|(n, _)| *n == name) else {
            let mut known: Vec<String> = EMBEDDED.iter().map(|(n, _)| (*n).to_owned()).collect();
            let place = match &self.dir {
                Some(d) => format!("{}/{name}.json does not exist; ", d.display()),
                None => "no --psych-designs directory is set; ".into(),
            };
            known.sort();
            return Err(DesignError::Unknown {
                name: name.to_owned(),
                known: format!("{place}built in: {}", known.join(", ")),
            });
        };
        Design::parse(name, text)
    }
}

fn read(name: &str, path: &Path) -> Result<Design, DesignError> {
    let fail = |reason: String| DesignError::Read {
        name: name.to_owned(),
        path: path.display().to_string(),
        reason,
    };
    let size = std::fs::metadata(path)
        .map_err(|e| fail(e.to_string()))?
        .len();
    if size > MAX_DESIGN_BYTES {
        return Err(fail(format!(
            "{size} bytes; a design file is at most {MAX_DESIGN_BYTES}"
        )));
    }
    let text = std::fs::read_to_string(path).map_err(|e| fail(e.to_string()))?;
    let design = Design::parse(&path.display().to_string(), &text)?;
    if design.name != name {
        return Err(DesignError::Field {
            design: path.display().to_string(),
            field: "name".into(),
            value: format!("{:?}", design.name),
            expected: format!("must be `{name}`, the file's name"),
        });
    }
    Ok(design)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn shipped() -> Design {
        Designs::default()
            .load(DEFAULT_DESIGN)
            .expect("the shipped design is valid")
    }

    #[test]
    fn the_shipped_design_is_the_papers_experiment_one() {
        let d = shipped();
        assert_eq!(d.eccentricities_deg.len(), 3);
        assert_eq!(d.directions_deg.len(), 4);
        assert_eq!(d.stimulus.duration_ms, 150.0);
        assert_eq!(d.inter_stimulus_ms, 2000.0);
        let labels: Vec<_> = d.gaps.iter().map(|g| g.label.as_str()).collect();
        assert_eq!(labels, ["touching", "small", "large"]);
        assert_eq!(d.trials(), 3 * 4 * 4 * 5);
    }

    /// The paper's experiments 2-4: motion under 300 ms; a random axis and three distractor
    /// levels, red in 3 and white in 4, where the cross is hidden and collisions may happen at
    /// the fixation.
    #[test]
    fn the_shipped_designs_are_the_papers_experiments_two_to_four() {
        let load = |n| Designs::default().load(n).expect("valid");
        let (e2, e3, e4) = (
            load("experiment2"),
            load("experiment3"),
            load("experiment4"),
        );
        for d in [&e2, &e3, &e4] {
            assert!(d.stimulus.motion_speed_deg_s.is_some_and(|v| v > 0.0));
            assert!(d.stimulus.duration_ms < 300.0);
        }
        assert!(e2.distractors.is_none() && e2.stimulus.pair_axis != "random");
        let (d3, d4) = (
            e3.distractors.as_ref().expect("3"),
            e4.distractors.as_ref().expect("4"),
        );
        assert_eq!((d3.colour.as_str(), d4.colour.as_str()), ("red", "white"));
        assert_eq!((d3.counts.len(), d4.counts.len()), (3, 3));
        assert_eq!(e3.stimulus.pair_axis, "random");
        assert!(e4.hide_cross_during_stimulus && !e3.hide_cross_during_stimulus);
        assert!(e4.eccentricities_deg.contains(&0.0));
        // The levels multiply the trials and the cells; every cell index is distinct.
        assert_eq!(e4.trials() % 3, 0);
        let mut seen = std::collections::HashSet::new();
        for e in 0..e4.eccentricities_deg.len() {
            for d in 0..e4.directions_deg.len() {
                for g in 0..e4.gaps.len() {
                    for l in 0..3 {
                        assert!(seen.insert(e4.cell(e, d, g, l)));
                    }
                }
            }
        }
        // Without distractors the numbering is experiment 1's.
        assert_eq!(shipped().cell(1, 2, 1, 0), (4 + 2) * 3 + 1);
        let mut bad = e3.clone();
        if let Some(d) = bad.distractors.as_mut() {
            d.colour = "blue".into();
        }
        let e = bad.validate().expect_err("colour").to_string();
        assert!(e.contains("`distractors.colour`"), "{e}");
        let mut bad = e3.clone();
        bad.stimulus.motion_speed_deg_s = Some(f64::NAN);
        let e = bad.validate().expect_err("speed").to_string();
        assert!(e.contains("`stimulus.motion_speed_deg_s`"), "{e}");
    }

    #[test]
    fn a_field_out_of_range_is_named_with_its_limit() {
        let mut d = shipped();
        d.gaps[1].gap_deg = -0.1;
        let e = d.validate().expect_err("refused").to_string();
        assert_eq!(
            e,
            "design `experiment1`: `gaps[1].gap_deg` = -0.1: must be within 0..=5 degrees"
        );
        let mut d = shipped();
        d.repetitions = 100;
        d.eccentricities_deg = vec![1.0; 16];
        let e = d.validate().expect_err("refused").to_string();
        assert!(
            e.contains("`repetitions`") && e.contains("at most 10000"),
            "{e}"
        );
        let mut d = shipped();
        d.responses.apart.keys = vec!["f".into()];
        let e = d.validate().expect_err("refused").to_string();
        assert!(e.contains("responses.apart.keys[0]"), "{e}");
    }

    #[test]
    fn unknown_and_malformed_fields_are_refused_by_name() {
        let text = EMBEDDED[0]
            .1
            .replacen("\"repetitions\"", "\"repetition\"", 1);
        let e = Design::parse("x", &text).expect_err("refused").to_string();
        assert!(e.contains("unknown field `repetition`"), "{e}");
        let text = EMBEDDED[0].1.replacen("\"blocks\": 4", "\"blocks\": -4", 1);
        let e = Design::parse("x", &text).expect_err("refused").to_string();
        assert!(e.contains("line"), "{e}");
        let e = Designs::default()
            .load("nope")
            .expect_err("unknown")
            .to_string();
        assert!(e.contains("built in: experiment1"), "{e}");
        let e = Designs::default()
            .load("../etc")
            .expect_err("refused")
            .to_string();
        assert!(e.contains("letters, digits"), "{e}");
    }
}
