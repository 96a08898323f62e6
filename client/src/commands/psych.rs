//! `foveal psych`: fit the paper's perceptual functions to a viewer's responses (`fit`), or
//! check that the fit recovers a known viewer (`simulate`).

use std::io::Write as _;
use std::path::PathBuf;

use foveal_psych::fit::cells;
use foveal_psych::model::{Function, Observer};
use foveal_psych::report::{self, Options};
use foveal_psych::simulate::{self as simulated, Design, coverage};
use foveal_psych::trial::{parse_csv_where, to_csv};

use super::{CommandError, Outcome};

/// What `foveal psych fit` is asked for.
#[derive(Debug, Clone, PartialEq)]
pub struct FitCommand {
    /// Results CSVs (one row per trial).
    pub results: Vec<PathBuf>,
    /// Where the report (`fit.md`), the figure (`fit.svg`) and the model (`model.txt`) go.
    pub out: Option<PathBuf>,
    /// Only the trials whose `(column, value)` pairs all hold (`--where`); empty: every trial.
    pub selection: Vec<(String, String)>,
    /// How to fit.
    pub options: Options,
}

/// What `foveal psych simulate` is asked for.
#[derive(Debug, Clone, PartialEq)]
pub struct SimulateCommand {
    /// The simulated viewers' observer (an F2 observer).
    pub observer: Observer,
    /// Viewers simulated.
    pub observers: usize,
    /// Repetitions of each cell of the default design (10: 400 trials).
    pub repetitions: u32,
    /// Bootstrap replicates per viewer.
    pub replicates: usize,
    /// Seed.
    pub seed: u64,
    /// Where to write every simulated trial (a results CSV `foveal psych fit` reads).
    pub trials_out: Option<PathBuf>,
}

/// Fit F1, F2 and F3 to the trials of `command.results`, pooled and per participant; print
/// the report and write it, its figure and the pooled model string under `out`.
pub fn fit(command: &FitCommand) -> Result<Outcome, CommandError> {
    if command.results.is_empty() {
        return Err(CommandError::Usage(
            "foveal psych fit: name at least one results CSV".into(),
        ));
    }
    let mut trials = Vec::new();
    for path in &command.results {
        let text = std::fs::read_to_string(path).map_err(|source| CommandError::Recording {
            action: "read",
            path: path.clone(),
            source,
        })?;
        trials.extend(
            parse_csv_where(&path.display().to_string(), &text, &command.selection)
                .map_err(|e| CommandError::Usage(e.to_string()))?,
        );
    }
    let selected: Vec<String> = command
        .selection
        .iter()
        .map(|(c, v)| format!("{c} = {v}"))
        .collect();
    if trials.is_empty() && !selected.is_empty() {
        return Err(CommandError::Usage(format!(
            "foveal psych fit: no valid trial has {} in the {} file(s) read",
            selected.join(" and "),
            command.results.len()
        )));
    }
    let fits = report::fit_groups(&trials, &command.options)
        .map_err(|e| CommandError::Usage(format!("foveal psych fit: {e}")))?;
    let mut text = report::markdown(&fits, &command.options);
    if !selected.is_empty() {
        text = format!(
            "Trials fitted: those with {} ({} trials).\n\n{text}",
            selected.join(" and "),
            trials.len()
        );
    }
    let pooled = &fits[0];
    let mut stdout = std::io::stdout().lock();
    write!(stdout, "{text}").map_err(CommandError::WriteStdout)?;
    if let Some(dir) = &command.out {
        let write = |name: &str, body: &str| {
            let path = dir.join(name);
            std::fs::create_dir_all(dir)
                .and_then(|()| std::fs::write(&path, body))
                .map_err(|source| CommandError::Recording {
                    action: "write",
                    path,
                    source,
                })
        };
        let f2 = pooled
            .standings
            .iter()
            .find(|s| s.fit.observer.function.name() == "F2")
            .map(|s| s.fit.observer)
            .ok_or_else(|| CommandError::Usage("F2 was not fitted".into()))?;
        let figure = foveal_psych::plot::svg(&cells(&trials), &f2, "foveal psych fit (pooled)")
            .map_err(|e| CommandError::Usage(format!("foveal psych fit: figure: {e}")))?;
        write("fit.md", &text)?;
        write("fit.svg", &figure)?;
        write("model.txt", &format!("{}\n", pooled.f2_model()))?;
        writeln!(
            stdout,
            "wrote {0}/fit.md, {0}/fit.svg and {0}/model.txt",
            dir.display()
        )
        .map_err(CommandError::WriteStdout)?;
    }
    Ok(Outcome::Success)
}

/// Simulate viewers with a known C (viewer `i` drawing from `seed + i`), fit each and print how often the fit recovers C within 20%
/// and how often its interval covers it. Fails (exit 1) when coverage is under 90%.
pub fn simulate(command: &SimulateCommand) -> Result<Outcome, CommandError> {
    let design = Design {
        repetitions: command.repetitions,
        ..Design::default()
    };
    let cov = coverage(
        &command.observer,
        &design,
        command.observers,
        command.replicates,
        command.seed,
    );
    if let Some(path) = &command.trials_out {
        let trials: Vec<_> = (0..command.observers as u64)
            .flat_map(|i| simulated::simulate(&command.observer, &design, command.seed + i))
            .collect();
        std::fs::write(path, to_csv(&trials)).map_err(|source| CommandError::Recording {
            action: "write",
            path: path.clone(),
            source,
        })?;
    }
    let mut stdout = std::io::stdout().lock();
    writeln!(
        stdout,
        "{} simulated viewers, {} trials each, true C = {} deg: median fitted C {:.3}; within 20% of the truth {:.0}%; 95% interval covers the truth {:.0}%; {} fits failed",
        command.observers,
        design.trials(),
        cov.truth,
        cov.median(),
        100.0 * cov.recovered(0.2),
        100.0 * cov.covered(),
        cov.failed
    )
    .map_err(CommandError::WriteStdout)?;
    Ok(if cov.covered() >= 0.9 && cov.failed == 0 {
        Outcome::Success
    } else {
        Outcome::Failure
    })
}

/// The F2 observer of `foveal psych simulate`'s flags.
pub fn f2_observer(c: f64, alpha: f64, beta: f64, guess: f64, lapse: f64) -> Observer {
    Observer {
        function: Function::F2 { c },
        alpha,
        beta,
        guess,
        lapse,
    }
}
