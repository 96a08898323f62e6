//! The paper's psychophysics in the browser: the `/psych` page's server side.
//!
//! The page (`web/src/psych/`, embedded with the viewer by [`crate::web`]) runs an experiment
//! whose conditions, levels and repetitions come from a design file ([`design`]), and sends each
//! trial here as it ends. The server keeps one results CSV per participant and session, with a
//! JSON header beside it ([`store`]), in the columns `foveal psych fit` reads ([`trial`]).
//!
//! - [`design`]: the design file, its checks, the shipped and the lab's designs.
//! - [`trial`]: one trial as posted, its checks against the design, its CSV row.
//! - [`store`]: sessions and their files, appended and synced trial by trial.
//! - [`fields`]: JSON read field by field, so every refusal names its field.
//! - [`http`]: the endpoint under `/psych/api/`: routes, the role check, bounded bodies.

pub mod design;
pub mod fields;
pub mod http;
pub mod store;
pub mod trial;

use std::path::PathBuf;

pub use http::Psych;

/// Where results go and where a lab's designs come from.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PsychConfig {
    /// The results directory (`--psych-results`), created with the first session.
    pub results_dir: PathBuf,
    /// The lab's designs (`--psych-designs`): `DIR/NAME.json`, before the built-in ones.
    pub designs_dir: Option<PathBuf>,
}

/// `--psych-results`' default: beside wherever the server was started.
pub const DEFAULT_RESULTS_DIR: &str = "psych-results";

impl Default for PsychConfig {
    fn default() -> Self {
        Self {
            results_dir: PathBuf::from(DEFAULT_RESULTS_DIR),
            designs_dir: None,
        }
    }
}
