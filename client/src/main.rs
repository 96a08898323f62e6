//! `foveal`: the command-line client of a foveal server.
//!
//! Parses arguments, sets up logging (stderr) and makes one call per subcommand into
//! `foveal_client::commands`; results go to stdout so that they can be piped while logs stay on
//! the terminal.

use std::io;
use std::process::ExitCode;

use clap::Parser;
use foveal_client::cli::{Cli, Command, PsychCommand};
use foveal_client::commands::{self, Outcome};
use tracing_subscriber::EnvFilter;

fn main() -> ExitCode {
    let cli = Cli::parse();
    tracing_subscriber::fmt()
        .with_env_filter(
            // zeromq logs each reconnection attempt as a warning; the Pupil bridge reports a
            // Pupil that has gone itself.
            EnvFilter::try_from_default_env()
                .unwrap_or_else(|_| EnvFilter::new("info,zeromq=error")),
        )
        // Colour only on a terminal, and never with NO_COLOR (https://no-color.org): a log
        // piped to a file or another program must read as plain text.
        .with_ansi(
            io::IsTerminal::is_terminal(&io::stderr())
                && std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty()),
        )
        .with_writer(io::stderr)
        .init();
    let runtime = match tokio::runtime::Builder::new_multi_thread()
        .enable_all()
        .build()
    {
        Ok(runtime) => runtime,
        Err(err) => {
            eprintln!("error: cannot start the async runtime: {err}");
            return ExitCode::FAILURE;
        }
    };
    match runtime.block_on(run(cli)) {
        Ok(outcome) => outcome.into(),
        Err(err) => {
            eprintln!("error: {err:#}");
            ExitCode::FAILURE
        }
    }
}

/// One library call per subcommand.
async fn run(cli: Cli) -> anyhow::Result<Outcome> {
    Ok(match cli.command {
        Command::Gaze(args) => commands::send(&args.server(), args.send(), args.input()).await?,
        Command::Bridge(args) => commands::send(&args.server(), args.send(), args.input()).await?,
        Command::Watch(args) => commands::watch(&args.server(), args.command()).await?,
        Command::Health(args) => {
            commands::health(&args.server(), args.service(), args.timeout()).await?
        }
        Command::Fixations(args) => commands::fixations(&args.command())?,
        Command::Load(args) => commands::load(&args.server(), args.command()).await?,
        Command::Psych(PsychCommand::Fit(args)) => commands::psych::fit(&args.command())?,
        Command::Psych(PsychCommand::Simulate(args)) => commands::psych::simulate(&args.command())?,
    })
}
