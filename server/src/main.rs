//! `foveal-server`: parse flags, set up logging, bind, and hand over to [`foveal_server::run`].

use anyhow::Context;
use clap::Parser;
use foveal_server::cli::Cli;

#[tokio::main]
async fn main() -> anyhow::Result<()> {
    let cli = Cli::parse();
    foveal_server::telemetry::init(&cli.log_level, cli.log_format)?;
    let mut config = cli.server_config()?;
    if cli.demo {
        tracing::warn!(
            bodies = foveal_server::cli::DEMO_BODIES,
            sphere_tests = foveal_server::cli::DEMO_TESTS,
            "--demo: a staged demonstration, with a sphere-test budget chosen to show the effect \
             rather than one this machine's frame time calls for, and the side by side on"
        );
    }
    config.security = cli.security()?;
    let listener = tokio::net::TcpListener::bind(cli.addr)
        .await
        .with_context(|| format!("binding {}", cli.addr))?;
    let health = match cli.health_addr {
        Some(addr) => Some(
            tokio::net::TcpListener::bind(addr)
                .await
                .with_context(|| format!("binding --health-addr {addr}"))?,
        ),
        None => None,
    };
    foveal_server::run_with_health(listener, health, config, shutdown_signal()).await?;
    Ok(())
}

/// Resolves on SIGINT (Ctrl-C) or, on Unix, SIGTERM (what `docker stop` sends).
async fn shutdown_signal() {
    let ctrl_c = async {
        if let Err(e) = tokio::signal::ctrl_c().await {
            tracing::error!(error = %e, "cannot listen for Ctrl-C");
            std::future::pending::<()>().await;
        }
    };
    #[cfg(unix)]
    let term = async {
        match tokio::signal::unix::signal(tokio::signal::unix::SignalKind::terminate()) {
            Ok(mut s) => {
                s.recv().await;
            }
            Err(e) => {
                tracing::error!(error = %e, "cannot listen for SIGTERM");
                std::future::pending::<()>().await;
            }
        }
    };
    #[cfg(not(unix))]
    let term = std::future::pending::<()>();
    tokio::select! {
        () = ctrl_c => tracing::info!("SIGINT received"),
        () = term => tracing::info!("SIGTERM received"),
    }
}
