//! One trial's record, and the results CSV: one row per trial, a header row of plain column
//! names, comma-separated, numbers in degrees of visual angle, so that PsychoPy's and R's
//! readers (`read.csv`) take it as it is.
//!
//! Reading needs the columns `participant`, `eccentricity_deg`, `gap_deg` and `response`
//! (`apart` or `touching`); any other column (timing, trial number, condition labels) is
//! carried by the file and ignored here. An optional `valid` column (`1`/`0`, `true`/`false`)
//! drops the trials a session marked invalid (a late frame, a broken fixation) and repeated.

use thiserror::Error;

/// One trial.
#[derive(Debug, Clone, PartialEq)]
pub struct Trial {
    /// Opaque participant id.
    pub participant: String,
    /// Eccentricity of the contact from the fixation (degrees).
    pub eccentricity_deg: f64,
    /// On-screen gap (degrees; 0 when the bodies touch).
    pub gap_deg: f64,
    /// Whether the participant reported "apart".
    pub apart: bool,
}

/// A results file that cannot be read.
#[derive(Debug, Error, PartialEq)]
pub enum TrialError {
    /// The file has no header row.
    #[error("{file}: empty, expected a header row naming at least {REQUIRED:?}")]
    Empty {
        /// The file.
        file: String,
    },
    /// A required column is missing.
    #[error("{file}: no `{column}` column (the header must name {REQUIRED:?})")]
    MissingColumn {
        /// The file.
        file: String,
        /// The column.
        column: &'static str,
    },
    /// A column a selection names is missing.
    #[error("{file}: no `{column}` column to select trials on")]
    MissingSelected {
        /// The file.
        file: String,
        /// The column.
        column: String,
    },
    /// A field does not parse or is out of range.
    #[error("{file} line {line}: `{column}` = `{value}`: {why}")]
    Field {
        /// The file.
        file: String,
        /// 1-based line number.
        line: usize,
        /// The column.
        column: &'static str,
        /// What it held.
        value: String,
        /// What it must be.
        why: &'static str,
    },
}

/// The columns reading needs.
pub const REQUIRED: [&str; 4] = ["participant", "eccentricity_deg", "gap_deg", "response"];

/// Gaps and eccentricities above this many degrees are refused: no display subtends more.
pub const MAX_DEGREES: f64 = 180.0;

/// The trials of a results CSV's text (`file` names it in errors).
pub fn parse_csv(file: &str, text: &str) -> Result<Vec<Trial>, TrialError> {
    parse_csv_where(file, text, &[])
}

/// [`parse_csv`], keeping only the rows whose every `(column, value)` of `selection` holds (the
/// field as written, e.g. `distractors` = `8` or `design` = `experiment4`): one condition of an
/// experiment fitted apart from the others.
pub fn parse_csv_where(
    file: &str,
    text: &str,
    selection: &[(String, String)],
) -> Result<Vec<Trial>, TrialError> {
    let mut lines = text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty());
    let Some((_, header)) = lines.next() else {
        return Err(TrialError::Empty { file: file.into() });
    };
    let names: Vec<&str> = header.split(',').map(|h| h.trim()).collect();
    let column = |name: &'static str| {
        names
            .iter()
            .position(|n| *n == name)
            .ok_or(TrialError::MissingColumn {
                file: file.into(),
                column: name,
            })
    };
    let [participant, ecc, gap, response] = [
        column(REQUIRED[0])?,
        column(REQUIRED[1])?,
        column(REQUIRED[2])?,
        column(REQUIRED[3])?,
    ];
    let valid = names.iter().position(|n| *n == "valid");
    let selected = selection
        .iter()
        .map(|(c, v)| {
            names
                .iter()
                .position(|n| n == c)
                .map(|i| (i, v.as_str()))
                .ok_or_else(|| TrialError::MissingSelected {
                    file: file.into(),
                    column: c.clone(),
                })
        })
        .collect::<Result<Vec<_>, _>>()?;
    let mut trials = Vec::new();
    for (i, line) in lines {
        let fields: Vec<&str> = line.split(',').map(|f| f.trim()).collect();
        let field = |index: usize, column: &'static str| {
            fields.get(index).copied().ok_or_else(|| TrialError::Field {
                file: file.into(),
                line: i + 1,
                column,
                value: String::new(),
                why: "missing (fewer fields than the header)",
            })
        };
        let bad = |column: &'static str, value: &str, why: &'static str| TrialError::Field {
            file: file.into(),
            line: i + 1,
            column,
            value: value.chars().take(40).collect(),
            why,
        };
        if selected
            .iter()
            .any(|&(i, v)| fields.get(i).copied() != Some(v))
        {
            continue;
        }
        if let Some(v) = valid {
            match field(v, "valid")? {
                "1" | "true" | "TRUE" | "True" => {}
                "0" | "false" | "FALSE" | "False" => continue,
                other => return Err(bad("valid", other, "expected 1, 0, true or false")),
            }
        }
        let degrees = |index: usize, column: &'static str| -> Result<f64, TrialError> {
            let raw = field(index, column)?;
            let v: f64 = raw.parse().map_err(|_| bad(column, raw, "not a number"))?;
            if !(0.0..=MAX_DEGREES).contains(&v) {
                return Err(bad(column, raw, "must be within 0..=180 degrees"));
            }
            Ok(v)
        };
        let apart = match field(response, "response")? {
            "apart" => true,
            "touching" => false,
            other => return Err(bad("response", other, "expected `apart` or `touching`")),
        };
        trials.push(Trial {
            participant: field(participant, "participant")?.to_string(),
            eccentricity_deg: degrees(ecc, "eccentricity_deg")?,
            gap_deg: degrees(gap, "gap_deg")?,
            apart,
        });
    }
    Ok(trials)
}

/// The trials as a results CSV with the columns [`parse_csv`] reads.
pub fn to_csv(trials: &[Trial]) -> String {
    let mut out = String::from("participant,eccentricity_deg,gap_deg,response\n");
    for t in trials {
        out += &format!(
            "{},{},{},{}\n",
            t.participant,
            t.eccentricity_deg,
            t.gap_deg,
            if t.apart { "apart" } else { "touching" }
        );
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_round_trip_and_extra_columns_are_ignored() {
        let text = "trial,participant,eccentricity_deg,gap_deg,response,valid,rt_ms\n\
                    1,p01,2.5,0.1,apart,1,420\n\
                    2,p01,10,0,touching,1,380\n\
                    3,p01,10,0.2,apart,0,390\n";
        let trials = parse_csv("s.csv", text).expect("parses");
        assert_eq!(trials.len(), 2, "the invalid trial is dropped");
        assert_eq!(parse_csv("s.csv", &to_csv(&trials)), Ok(trials));
        // One condition apart: only the rows whose fields match, a missing column named.
        let text = "participant,eccentricity_deg,gap_deg,response,distractors\n\
                    p1,2,0.1,apart,4\np1,5,0.1,touching,8\np1,10,0.2,apart,8\n";
        let sel = |c: &str, v: &str| vec![(c.to_string(), v.to_string())];
        let eight = parse_csv_where("s.csv", text, &sel("distractors", "8")).expect("parses");
        assert_eq!(eight.len(), 2);
        assert!(eight.iter().all(|t| t.eccentricity_deg > 2.0));
        assert!(
            parse_csv_where("s.csv", text, &sel("distractors", "16"))
                .expect("parses")
                .is_empty()
        );
        let e = parse_csv_where("s.csv", text, &sel("design", "x")).expect_err("no column");
        assert!(e.to_string().contains("no `design` column"), "{e}");
    }

    #[test]
    fn bad_rows_name_the_file_line_and_column() {
        let e = parse_csv(
            "s.csv",
            "participant,eccentricity_deg,gap_deg,response\np,NaN,0,apart\n",
        )
        .expect_err("refused");
        assert_eq!(
            e.to_string(),
            "s.csv line 2: `eccentricity_deg` = `NaN`: must be within 0..=180 degrees"
        );
        let e = parse_csv("s.csv", "participant,gap_deg,response\n").expect_err("refused");
        assert!(
            e.to_string().contains("no `eccentricity_deg` column"),
            "{e}"
        );
        let e = parse_csv(
            "s.csv",
            "participant,eccentricity_deg,gap_deg,response\np,1,0,yes\n",
        )
        .expect_err("refused");
        assert!(
            e.to_string().contains("expected `apart` or `touching`"),
            "{e}"
        );
        assert_eq!(
            parse_csv("s.csv", "\n"),
            Err(TrialError::Empty {
                file: "s.csv".into()
            })
        );
    }
}
