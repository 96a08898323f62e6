//! Where the viewer looks in each frame: a seeded script of fixations and saccades, or a recorded
//! eye-tracker trace (paper sections 1.2 and 4: the fixation point f of every frame).
//!
//! Both sources answer one question, [`Gaze::at`]: the fixation to hand the engine for a frame that
//! starts at simulated time `t` seconds. The script is the default because it is reproducible from a
//! seed on any machine; the recording is the realistic alternative.

use std::path::{Path, PathBuf};

use foveal_engine::Fixation;
use foveal_engine::Viewer as Camera;
use foveal_engine::world::World;
use foveal_gaze::csv::CsvGazeReader;
use foveal_gaze::rng::SplitMix64;
use foveal_gaze::viewer::{Placement, Viewer, gaussian_pair};

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

/// Who watches the open loop's frames: how the viewer's fixations are placed. The study reports
/// its headlines per viewer model, because how much gaze scheduling gains depends on where people
/// look (`docs/DESIGN.md`, "Viewer models").
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ViewerModel {
    /// The caller's gaze; in the study the seeded script, fixating uniformly over the central 70%
    /// of the screen ([`ScriptedGaze`]).
    Script,
    /// The script's timeline with fixations drawn from the central bias of scene viewing
    /// ([`central_bias`]).
    CentralBias,
    /// The script's timeline with each fixation drawn toward the scene's collisions and motion
    /// ([`scene_target`]).
    SceneDriven,
    /// The shipped EyeLink recording ([`RECORDING`]), replayed in a loop.
    Recorded,
}

impl ViewerModel {
    /// Name in condition labels and tables.
    pub fn name(self) -> &'static str {
        match self {
            Self::Script => "uniform script",
            Self::CentralBias => "central-bias viewer",
            Self::SceneDriven => "scene-driven viewer",
            Self::Recorded => "recorded viewer",
        }
    }
}

/// Clarke and Tatler's (2014, Vision Research 102: 41-51) baseline for image-independent fixation
/// placement in scene viewing: a Gaussian about the screen centre with horizontal variance 0.22
/// and vertical variance 0.45 times that, in units where the screen's width spans [-1, 1]. As
/// standard deviations in fractions of the screen's width and height (`aspect` = width / height).
pub fn central_bias(aspect: f64) -> Placement {
    const VAR_X: f64 = 0.22;
    const NU: f64 = 0.45;
    // A half-width is one unit: a fraction of the width is half a unit, a fraction of the height
    // half a unit times the aspect.
    Placement::CentralBias {
        sd_x: VAR_X.sqrt() / 2.0,
        sd_y: (NU * VAR_X).sqrt() / 2.0 * aspect,
    }
}

/// The scene-driven viewer's saliency rule, stated in the protocol: a new fixation goes, with this
/// probability, to a real collision of the frame (one of those on screen, uniformly; where its
/// two bodies' centres meet), and otherwise to a body drawn with probability proportional to its
/// speed on screen. Collisions and motion are what this stimulus offers the eye; there is no
/// measured saliency model of it.
pub const SCENE_COLLISION_SHARE: f64 = 0.6;

/// The scene-driven viewer lands its saccades with Gaussian error of this standard deviation per
/// axis, degrees of visual angle (saccadic landing scatter is of the order of 10% of the
/// amplitude; half a degree is a typical such error for the amplitudes here).
pub const SCENE_LANDING_SD_DEG: f64 = 0.5;

/// The next fixation of the scene-driven viewer on this frame ([`SCENE_COLLISION_SHARE`]):
/// `colliding(k)` says whether candidate pair `k` truly collides; `px_per_deg` converts the
/// landing error. Normalised screen position, clamped to the screen; the screen centre if nothing
/// is on screen.
pub fn scene_target(
    rng: &mut SplitMix64,
    camera: &Camera,
    world: &World,
    candidates: &[(u32, u32)],
    colliding: &dyn Fn(usize) -> bool,
    px_per_deg: f64,
) -> [f64; 2] {
    let (w, h) = (
        f64::from(camera.display.width_px),
        f64::from(camera.display.height_px),
    );
    let on_screen = |p: [f64; 2]| (0.0..=w).contains(&p[0]) && (0.0..=h).contains(&p[1]);
    let pick = rng.next_f64();
    let mut target = None;
    if pick < SCENE_COLLISION_SHARE {
        let hits: Vec<[f64; 2]> = candidates
            .iter()
            .enumerate()
            .filter(|&(k, _)| colliding(k))
            .map(|(_, &(a, b))| {
                let (pa, pb) = (world.position[a as usize], world.position[b as usize]);
                camera.project((pa + pb) * 0.5)
            })
            .filter(|&p| on_screen(p))
            .collect();
        if !hits.is_empty() {
            let k = ((rng.next_f64() * hits.len() as f64) as usize).min(hits.len() - 1);
            target = Some(hits[k]);
        }
    }
    let target = target.unwrap_or_else(|| {
        // Speed on screen: the velocity across the line of sight, scaled by the projection.
        let focal = camera.focal_px();
        let speeds: Vec<(f64, [f64; 2])> = world
            .position
            .iter()
            .zip(&world.velocity)
            .filter_map(|(&p, &v)| {
                let at = camera.project(p);
                let depth = camera.eye.z - p.z;
                (on_screen(at) && depth > 0.0).then(|| (v.x.hypot(v.y) * focal / depth, at))
            })
            .collect();
        let total: f64 = speeds.iter().map(|s| s.0).sum();
        if total <= 0.0 || !total.is_finite() {
            return [0.5 * w, 0.5 * h];
        }
        let mut left = rng.next_f64() * total;
        for &(s, at) in &speeds {
            left -= s;
            if left <= 0.0 {
                return at;
            }
        }
        speeds.last().map_or([0.5 * w, 0.5 * h], |s| s.1)
    });
    let (gx, gy) = gaussian_pair(rng);
    let sd_px = SCENE_LANDING_SD_DEG * px_per_deg;
    [
        ((target[0] + gx * sd_px) / w).clamp(0.0, 1.0),
        ((target[1] + gy * sd_px) / h).clamp(0.0, 1.0),
    ]
}

/// The shipped eye-tracker recording the recorded viewer replays (EyeLink, 1,000 Hz, left eye,
/// 1920x1080; `data/gaze/README.md`).
pub const RECORDING: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../../data/gaze/eyelink-1000hz-left.samples.csv"
);

/// What a scene-driven viewer looks at when it chooses: the frame's bodies, candidates and which
/// of them truly collide.
pub struct SceneGlance<'a> {
    /// Camera and display.
    pub camera: &'a Camera,
    /// Bodies.
    pub world: &'a World,
    /// Candidate pairs.
    pub candidates: &'a [(u32, u32)],
    /// Whether candidate `k` truly collides.
    pub colliding: &'a dyn Fn(usize) -> bool,
    /// Pixels per degree at the screen centre.
    pub px_per_deg: f64,
}

impl std::fmt::Debug for SceneGlance<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("SceneGlance")
            .field("bodies", &self.world.len())
            .field("candidates", &self.candidates.len())
            .field("px_per_deg", &self.px_per_deg)
            .finish_non_exhaustive()
    }
}

/// One viewer model's gaze over a run, frame by frame: the fixation at simulated time `t`. Built
/// afresh for each replay of a run's frames, so every replay sees the same gaze.
#[derive(Debug, Clone)]
pub enum ViewerTrack {
    /// [`ViewerModel::Script`]: the caller's gaze.
    Script,
    /// A timeline of the script's kind with its own placement.
    Timeline(Viewer),
    /// A recording.
    Recorded(RecordedGaze),
}

impl ViewerTrack {
    /// The track of `model` for the run seeded by `seed` on a screen of this `aspect` (width /
    /// height); the recording, if needed, from `recording`.
    pub fn new(
        model: ViewerModel,
        seed: u64,
        aspect: f64,
        recording: Option<&RecordedGaze>,
    ) -> Result<Self, GazeError> {
        Ok(match model {
            ViewerModel::Script => Self::Script,
            ViewerModel::CentralBias => {
                Self::Timeline(Viewer::with_placement(seed, central_bias(aspect)))
            }
            ViewerModel::SceneDriven => {
                Self::Timeline(Viewer::with_placement(seed, Placement::Chosen))
            }
            ViewerModel::Recorded => match recording {
                Some(r) => Self::Recorded(r.clone()),
                None => Self::Recorded(RecordedGaze::from_csv(Path::new(RECORDING))?),
            },
        })
    }

    /// The fixation at `t`: `script` answers for [`ViewerModel::Script`]; a scene-driven viewer
    /// starting a saccade chooses its target from `scene`.
    pub fn at(
        &mut self,
        t: f64,
        script: &mut dyn FnMut(f64) -> Fixation,
        scene: &SceneGlance<'_>,
    ) -> Fixation {
        match self {
            Self::Script => script(t),
            Self::Timeline(v) => {
                let g = v.at_choosing(t, &mut |rng, _| {
                    scene_target(
                        rng,
                        scene.camera,
                        scene.world,
                        scene.candidates,
                        scene.colliding,
                        scene.px_per_deg,
                    )
                });
                Fixation::at(g.x, g.y)
            }
            Self::Recorded(r) => r.at(t.max(0.0)).unwrap_or(Fixation::at(0.5, 0.5)),
        }
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

    /// The scene-driven viewer looks at the frame's collisions (within its landing error) more
    /// often than its share says it aims for them by chance, and at moving bodies otherwise; the
    /// same seed gives the same gaze, and every model's track stays on screen.
    #[test]
    fn scene_driven_viewer_looks_where_the_collisions_are() {
        use foveal_engine::{SceneConfig, SimConfig, Simulation};
        let mut sim = Simulation::new(SimConfig {
            scene: SceneConfig::paper(300, 7),
            ..SimConfig::default()
        })
        .expect("scene");
        for _ in 0..30 {
            sim.step(None, &foveal_engine::FrozenClock);
        }
        let hits: std::collections::HashSet<(u32, u32)> =
            sim.exact_colliding_pairs().into_iter().collect();
        let input = sim.frame_input();
        let slot_hits: Vec<bool> = input
            .candidates
            .iter()
            .map(|&p| hits.contains(&sim.id_pair(p)))
            .collect();
        assert!(slot_hits.iter().any(|&h| h), "no collision in the frame");
        let colliding = |k: usize| slot_hits[k];
        let camera = input.viewer;
        let px_per_deg = camera.display.pixels_per_degree();
        let points: Vec<[f64; 2]> = input
            .candidates
            .iter()
            .enumerate()
            .filter(|&(k, _)| slot_hits[k])
            .map(|(_, &(a, b))| {
                let w = input.world;
                camera.project((w.position[a as usize] + w.position[b as usize]) * 0.5)
            })
            .collect();
        let mut rng = SplitMix64::new(11);
        let draws = 2_000;
        let near = (0..draws)
            .filter(|_| {
                let t = scene_target(
                    &mut rng,
                    camera,
                    input.world,
                    input.candidates,
                    &colliding,
                    px_per_deg,
                );
                let px = camera.to_pixels(t[0], t[1]);
                points
                    .iter()
                    .any(|p| camera.display.visual_angle_deg(*p, px) < 2.0)
            })
            .count();
        let share = near as f64 / f64::from(draws);
        assert!(share > 0.9 * SCENE_COLLISION_SHARE, "{share}");
        let glance = SceneGlance {
            camera,
            world: input.world,
            candidates: input.candidates,
            colliding: &colliding,
            px_per_deg,
        };
        for model in [
            ViewerModel::Script,
            ViewerModel::CentralBias,
            ViewerModel::SceneDriven,
            ViewerModel::Recorded,
        ] {
            let track = |seed| {
                let mut tr = ViewerTrack::new(model, seed, 16.0 / 9.0, None).expect("track");
                let mut script = ScriptedGaze::new(seed);
                (0..300)
                    .map(|i| tr.at(f64::from(i) / 60.0, &mut |t| script.at(t), &glance))
                    .collect::<Vec<_>>()
            };
            let a = track(3);
            assert_eq!(a, track(3), "{model:?}");
            assert!(
                a.iter()
                    .all(|f| (0.0..=1.0).contains(&f.x) && (0.0..=1.0).contains(&f.y)),
                "{model:?}"
            );
            assert!(a.windows(2).any(|w| w[0] != w[1]), "{model:?} never moves");
        }
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
