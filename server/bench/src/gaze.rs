//! Where the viewer looks in each frame: a seeded script of fixations and saccades, or a recorded
//! eye-tracker trace (paper sections 1.2 and 4: the fixation point f of every frame).
//!
//! Both sources answer one question, [`Gaze::at`]: the fixation to hand the engine for a frame that
//! starts at simulated time `t` seconds. The script is the default because it is reproducible from a
//! seed on any machine; the recording is the realistic alternative.

use std::path::{Path, PathBuf};

use foveal_engine::Fixation;
use foveal_gaze::csv::CsvGazeReader;
use foveal_gaze::viewer::Viewer;

/// The scripted viewer of `foveal-gaze` (the same one `foveal gaze saccades` streams), asked for
/// the fixation at each frame's start.
#[derive(Debug, Clone)]
pub struct ScriptedGaze(Viewer);

impl ScriptedGaze {
    /// A script fixed by `seed`.
    pub fn new(seed: u64) -> Self {
        Self(Viewer::new(seed))
    }

    /// The gaze at time `t` (seconds, non-decreasing across calls is fastest but not required).
    pub fn at(&mut self, t: f64) -> Fixation {
        let g = self.0.at(t);
        Fixation::at(g.x, g.y)
    }

    /// Fixation durations (seconds) of the script up to time `t`: for checking the script.
    pub fn fixation_durations(&mut self, t: f64) -> Vec<f64> {
        self.0.fixation_durations(t)
    }
}

/// Why a recorded gaze trace could not be used.
#[derive(Debug, thiserror::Error)]
pub enum GazeError {
    /// The file could not be read.
    #[error("cannot read gaze trace {path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
    /// A line does not parse (bad header, a field that is not a number, no screen size for
    /// pixel gaze), or time goes backwards.
    #[error("gaze trace {path}, line {line}: {what}")]
    Line {
        /// The file.
        path: PathBuf,
        /// 1-based line number.
        line: usize,
        /// What is wrong.
        what: String,
    },
    /// Not a single usable sample.
    #[error("gaze trace {path} has no valid sample")]
    Empty {
        /// The file.
        path: PathBuf,
    },
}

/// A recorded trace, read by the gaze crate's CSV reader: `t_s,xpos,ypos[,ps]` in pixels of the
/// screen the file declares (`# screen 1920x1080 px`), or normalised `t_s,x,y[,validity]`; empty
/// fields for missing samples (blinks, track loss). Replayed in a loop when the study outlasts it.
#[derive(Debug, Clone)]
pub struct RecordedGaze {
    /// Valid samples: time (s, from the first sample) and normalised position.
    samples: Vec<(f64, [f64; 2])>,
    /// Length of one loop of the recording (s).
    period_s: f64,
}

impl RecordedGaze {
    /// Read a samples CSV. Lines starting with `#` are comments; the first other line is the header.
    pub fn from_csv(path: &Path) -> Result<Self, GazeError> {
        let text = std::fs::read_to_string(path).map_err(|source| GazeError::Io {
            path: path.to_owned(),
            source,
        })?;
        Self::parse(&text, path)
    }

    /// Parse the text of a samples CSV (`path` only names the source in errors). The first bad
    /// line is an error: a study must not run on a silently shortened trace.
    pub fn parse(text: &str, path: &Path) -> Result<Self, GazeError> {
        let mut samples = Vec::new();
        let mut first_t = None;
        let mut last_t = f64::NEG_INFINITY;
        let mut reader = CsvGazeReader::new(text.as_bytes());
        while let Some(result) = reader.next() {
            let s = result.map_err(|e| GazeError::Line {
                path: path.to_owned(),
                line: e.line(),
                what: e.to_string(),
            })?;
            let line = reader.line();
            if s.t_s < last_t {
                return Err(GazeError::Line {
                    path: path.to_owned(),
                    line,
                    what: format!("time {} goes backwards from {last_t}", s.t_s),
                });
            }
            last_t = s.t_s;
            let t0 = *first_t.get_or_insert(s.t_s);
            if s.is_valid() {
                samples.push((s.t_s - t0, [s.x, s.y]));
            }
        }
        let Some(&(t_last, _)) = samples.last() else {
            return Err(GazeError::Empty {
                path: path.to_owned(),
            });
        };
        let end = last_t - first_t.unwrap_or(0.0);
        Ok(Self {
            samples,
            period_s: end.max(t_last) + 1e-3,
        })
    }

    /// Number of valid samples.
    pub fn len(&self) -> usize {
        self.samples.len()
    }

    /// Whether there is no valid sample (never true for a parsed trace).
    pub fn is_empty(&self) -> bool {
        self.samples.is_empty()
    }

    /// Duration of one loop (s).
    pub fn period_s(&self) -> f64 {
        self.period_s
    }

    /// The latest valid sample at or before `t` (looping), with its age; `None` before the first.
    pub fn at(&self, t: f64) -> Option<Fixation> {
        let tl = t.rem_euclid(self.period_s);
        let i = self.samples.partition_point(|s| s.0 <= tl);
        let (ts, p) = if i == 0 {
            // Before the first valid sample of this loop: hold the last one of the previous loop.
            if t < self.period_s {
                return None;
            }
            let (ts, p) = *self.samples.last()?;
            (ts - self.period_s, p)
        } else {
            self.samples[i - 1]
        };
        Some(Fixation {
            age_s: (tl - ts).max(0.0),
            ..Fixation::at(p[0], p[1])
        })
    }
}

/// A gaze source for one run.
#[derive(Debug, Clone)]
pub enum Gaze {
    /// Seeded script.
    Scripted(ScriptedGaze),
    /// Recorded trace.
    Recorded(RecordedGaze),
}

impl Gaze {
    /// Fixation for a frame starting at `t` seconds.
    pub fn at(&mut self, t: f64) -> Option<Fixation> {
        match self {
            Self::Scripted(s) => Some(s.at(t)),
            Self::Recorded(r) => r.at(t),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn script_is_seeded_and_durations_are_realistic() {
        let mut a = ScriptedGaze::new(7);
        let mut b = ScriptedGaze::new(7);
        let mut c = ScriptedGaze::new(8);
        let ts: Vec<f64> = (0..600).map(|i| f64::from(i) / 60.0).collect();
        let fa: Vec<_> = ts.iter().map(|&t| a.at(t)).collect();
        let fb: Vec<_> = ts.iter().map(|&t| b.at(t)).collect();
        let fc: Vec<_> = ts.iter().map(|&t| c.at(t)).collect();
        assert_eq!(fa, fb);
        assert_ne!(fa, fc);
        let d = a.fixation_durations(10.0);
        assert!(d.len() > 15, "{}", d.len());
        assert!(d.iter().all(|&x| (0.15..=0.4).contains(&x)), "{d:?}");
        assert!(
            fa.iter()
                .all(|f| (0.0..=1.0).contains(&f.x) && (0.0..=1.0).contains(&f.y))
        );
    }

    #[test]
    fn recorded_trace_holds_last_valid_sample_and_loops() {
        let csv = "# screen 1920x1080 px\nt_s,xpos,ypos,ps\n0.000,960,540,1\n0.010,,,\n0.020,1920,0,1\n0.030,,,\n";
        let g = RecordedGaze::parse(csv, Path::new("mem")).expect("parses");
        assert_eq!(g.len(), 2);
        let f = g.at(0.015).expect("sample");
        assert_eq!((f.x, f.y), (0.5, 0.5));
        assert!((f.age_s - 0.015).abs() < 1e-12);
        let f = g.at(0.025).expect("sample");
        assert_eq!((f.x, f.y), (1.0, 0.0));
        // Looped: just after the period starts again, the first sample is back.
        let f = g.at(g.period_s() + 0.001).expect("looped");
        assert_eq!((f.x, f.y), (0.5, 0.5));
    }

    #[test]
    fn recorded_trace_errors_name_the_problem() {
        let p = Path::new("mem");
        assert!(matches!(
            RecordedGaze::parse("a,b,c\n", p),
            Err(GazeError::Line { line: 1, .. })
        ));
        assert!(matches!(
            RecordedGaze::parse("t_s,xpos,ypos,ps\n0,x,1,1\n", p),
            Err(GazeError::Line { line: 2, .. })
        ));
        assert!(matches!(
            RecordedGaze::parse("t_s,xpos,ypos,ps\n0,,,\n", p),
            Err(GazeError::Empty { .. })
        ));
        assert!(matches!(
            RecordedGaze::parse("# screen 10x10 px\nt_s,xpos,ypos,ps\n1,1,1,1\n0,1,1,1\n", p),
            Err(GazeError::Line { line: 4, .. })
        ));
        // Pixel gaze with no screen declared is an error, not a guess.
        assert!(matches!(
            RecordedGaze::parse("t_s,xpos,ypos,ps\n0,1,1,1\n", p),
            Err(GazeError::Line { line: 2, .. })
        ));
    }
}
