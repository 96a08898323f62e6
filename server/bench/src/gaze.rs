//! Where the viewer looks in each frame: a seeded script of fixations and saccades, or a recorded
//! eye-tracker trace (paper sections 1.2 and 4: the fixation point f of every frame).
//!
//! Both sources answer one question, [`Gaze::at`]: the fixation to hand the engine for a frame that
//! starts at simulated time `t` seconds. The script is the default because it is reproducible from a
//! seed on any machine; the recording is the realistic alternative.

use std::path::{Path, PathBuf};

use foveal_engine::Fixation;

/// Screen of the recorded traces (DESIGN.md; `shared/data/gaze/README.md`): 1920x1080 px, origin
/// top-left.
pub const RECORDED_SCREEN_PX: [f64; 2] = [1920.0, 1080.0];

/// splitmix64: a tiny, well-mixed generator, enough for gaze scripts (the engine has its own PRNG
/// for scenes; keeping them apart means a script change never changes a scene).
#[derive(Debug, Clone)]
pub struct SplitMix64(u64);

impl SplitMix64 {
    /// A generator whose whole sequence is fixed by `seed`.
    pub fn new(seed: u64) -> Self {
        Self(seed)
    }

    /// Next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    pub fn next_f64(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }

    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next_f64()
    }
}

/// One segment of a gaze script: hold still at `to` (fixation) or move from `from` to `to` (saccade).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Segment {
    start_s: f64,
    end_s: f64,
    from: [f64; 2],
    to: [f64; 2],
}

/// A scripted viewer: fixations of 150-400 ms (uniform) at uniformly random points of the central
/// 70% of the screen, joined by saccades whose duration follows the main sequence
/// (about 21 ms + 2.2 ms per degree of amplitude; here 20-60 ms by on-screen distance). During a
/// saccade the reported gaze moves linearly, as a tracker's samples do.
#[derive(Debug, Clone)]
pub struct ScriptedGaze {
    rng: SplitMix64,
    segments: Vec<Segment>,
}

/// Fixation durations of the script, seconds (reading and scene viewing: 150-400 ms).
pub const FIXATION_S: (f64, f64) = (0.150, 0.400);
/// Fixation targets lie in [MARGIN, 1 - MARGIN] of both normalised screen axes.
const MARGIN: f64 = 0.15;

impl ScriptedGaze {
    /// A script fixed by `seed`.
    pub fn new(seed: u64) -> Self {
        let mut rng = SplitMix64::new(seed ^ 0x6A5E_5EED_0000_0001);
        let p = [
            rng.range(MARGIN, 1.0 - MARGIN),
            rng.range(MARGIN, 1.0 - MARGIN),
        ];
        let d = rng.range(FIXATION_S.0, FIXATION_S.1);
        Self {
            rng,
            segments: vec![Segment {
                start_s: 0.0,
                end_s: d,
                from: p,
                to: p,
            }],
        }
    }

    fn extend_to(&mut self, t: f64) {
        while let Some(&last) = self.segments.last() {
            if last.end_s > t {
                break;
            }
            let from = last.to;
            let to = [
                self.rng.range(MARGIN, 1.0 - MARGIN),
                self.rng.range(MARGIN, 1.0 - MARGIN),
            ];
            // Normalised distance 0..1 maps to ~0..40 degrees on a desktop display.
            let amplitude = (to[0] - from[0]).hypot(to[1] - from[1]);
            let saccade = (0.020 + 0.040 * amplitude.min(1.0)).min(0.060);
            let fix = self.rng.range(FIXATION_S.0, FIXATION_S.1);
            let s0 = last.end_s;
            self.segments.push(Segment {
                start_s: s0,
                end_s: s0 + saccade,
                from,
                to,
            });
            self.segments.push(Segment {
                start_s: s0 + saccade,
                end_s: s0 + saccade + fix,
                from: to,
                to,
            });
        }
    }

    /// The gaze at time `t` (seconds, non-decreasing across calls is fastest but not required).
    pub fn at(&mut self, t: f64) -> Fixation {
        self.extend_to(t);
        let i = self
            .segments
            .partition_point(|s| s.end_s <= t)
            .min(self.segments.len() - 1);
        let s = self.segments[i];
        let u = if s.end_s > s.start_s {
            ((t - s.start_s) / (s.end_s - s.start_s)).clamp(0.0, 1.0)
        } else {
            1.0
        };
        Fixation::at(
            s.from[0] + (s.to[0] - s.from[0]) * u,
            s.from[1] + (s.to[1] - s.from[1]) * u,
        )
    }

    /// Fixation durations (seconds) of the script up to time `t`: for checking the script.
    pub fn fixation_durations(&mut self, t: f64) -> Vec<f64> {
        self.extend_to(t);
        self.segments
            .iter()
            .filter(|s| s.from == s.to && s.end_s <= t)
            .map(|s| s.end_s - s.start_s)
            .collect()
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
    /// The header is not `t_s,xpos,ypos[,ps]`.
    #[error("gaze trace {path}: expected a header `t_s,xpos,ypos,ps`, found {found:?}")]
    Header {
        /// The file.
        path: PathBuf,
        /// The header line seen (or empty).
        found: String,
    },
    /// A field is not a number, or time goes backwards.
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

/// A recorded trace: `t_s,xpos,ypos,ps` samples, gaze in pixels of a 1920x1080 screen, empty fields
/// for missing samples (blinks, track loss). Replayed in a loop when the study outlasts it.
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

    /// Parse the text of a samples CSV (`path` only names the source in errors).
    pub fn parse(text: &str, path: &Path) -> Result<Self, GazeError> {
        let mut lines = text
            .lines()
            .enumerate()
            .filter(|(_, l)| !l.trim().is_empty() && !l.trim_start().starts_with('#'));
        let header = lines.next().map(|(_, l)| l.trim()).unwrap_or_default();
        let cols: Vec<&str> = header.split(',').map(str::trim).collect();
        if cols.len() < 3 || cols[0] != "t_s" || cols[1] != "xpos" || cols[2] != "ypos" {
            return Err(GazeError::Header {
                path: path.to_owned(),
                found: header.to_owned(),
            });
        }
        let line_err = |line: usize, what: String| GazeError::Line {
            path: path.to_owned(),
            line: line + 1,
            what,
        };
        let mut samples = Vec::new();
        let mut first_t = None;
        let mut last_t = f64::NEG_INFINITY;
        for (i, l) in lines {
            let f: Vec<&str> = l.split(',').map(str::trim).collect();
            let num = |k: usize| -> Result<Option<f64>, GazeError> {
                match f.get(k).copied().unwrap_or("") {
                    "" | "." => Ok(None),
                    s => s.parse::<f64>().map(Some).map_err(|_| {
                        line_err(i, format!("field {} is not a number: {s:?}", k + 1))
                    }),
                }
            };
            let Some(t) = num(0)? else {
                return Err(line_err(i, "missing time".into()));
            };
            if !t.is_finite() || t < last_t {
                return Err(line_err(
                    i,
                    format!("time {t} is not finite or goes backwards"),
                ));
            }
            last_t = t;
            let t0 = *first_t.get_or_insert(t);
            if let (Some(x), Some(y)) = (num(1)?, num(2)?)
                && x.is_finite()
                && y.is_finite()
            {
                samples.push((
                    t - t0,
                    [x / RECORDED_SCREEN_PX[0], y / RECORDED_SCREEN_PX[1]],
                ));
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
            x: p[0],
            y: p[1],
            age_s: (tl - ts).max(0.0),
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
        let csv =
            "# comment\nt_s,xpos,ypos,ps\n0.000,960,540,1\n0.010,,,\n0.020,1920,0,1\n0.030,,,\n";
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
            Err(GazeError::Header { .. })
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
            RecordedGaze::parse("t_s,xpos,ypos,ps\n1,1,1,1\n0,1,1,1\n", p),
            Err(GazeError::Line { line: 3, .. })
        ));
    }
}
