//! Pause, Resume, Step, Restart and InspectBody: a researcher's controls over the running loop.
//!
//! Each is a command to the frame loop answered at its next frame boundary (a paused loop answers
//! at once), so the loop's thread alone ever touches the simulation. Restart is a Configure of the
//! seed and goes through Configure's checks and log.

use std::sync::mpsc;
use std::time::Duration;

use foveal_proto::pb;
use tokio::sync::oneshot;
use tonic::{Request, Status};

use crate::auth::Caller;
use crate::frame_loop::{Command, LoopState, StepRefused};

/// The most frames one Step may simulate: 10 s of a 60 Hz loop.
pub const MAX_STEP_FRAMES: u32 = 600;

/// How long a control call waits for the loop: a frame at the slowest rate plus a long step. A Step
/// of many long frames may take longer; its frames are simulated regardless.
const LOOP_TIMEOUT: Duration = Duration::from_secs(30);

/// Log a control call with its peer and role, as Configure is logged.
pub fn log_call<T>(method: &str, request: &Request<T>) {
    let peer = request.remote_addr();
    let role = request
        .extensions()
        .get::<Caller>()
        .map_or("open", Caller::role_name);
    tracing::info!(?peer, role, method, "loop control");
}

/// Send `cmd` to the loop and wait for its answer on `rx`.
async fn ask<T>(
    commands: &mpsc::Sender<Command>,
    cmd: Command,
    rx: oneshot::Receiver<T>,
    what: &str,
) -> Result<T, Status> {
    commands
        .send(cmd)
        .map_err(|_| Status::unavailable("the frame loop is not running"))?;
    tokio::time::timeout(LOOP_TIMEOUT, rx)
        .await
        .map_err(|_| {
            Status::deadline_exceeded(format!(
                "the frame loop did not answer {what} within {} s",
                LOOP_TIMEOUT.as_secs()
            ))
        })?
        .map_err(|_| Status::unavailable(format!("the frame loop stopped before {what}")))
}

fn to_pb(s: LoopState) -> pb::LoopState {
    pb::LoopState {
        paused: s.paused,
        frames: s.frames,
    }
}

/// Pause the loop.
pub async fn pause(commands: &mpsc::Sender<Command>) -> Result<pb::LoopState, Status> {
    let (tx, rx) = oneshot::channel();
    ask(commands, Command::Pause(tx), rx, "Pause")
        .await
        .map(to_pb)
}

/// Resume the loop.
pub async fn resume(commands: &mpsc::Sender<Command>) -> Result<pb::LoopState, Status> {
    let (tx, rx) = oneshot::channel();
    ask(commands, Command::Resume(tx), rx, "Resume")
        .await
        .map(to_pb)
}

/// The frames a Step asks for, checked: 0 means 1.
pub fn step_frames(frames: u32) -> Result<u32, Status> {
    match frames {
        0 => Ok(1),
        1..=MAX_STEP_FRAMES => Ok(frames),
        _ => Err(Status::invalid_argument(format!(
            "StepRequest.frames = {frames}: must be in 0..={MAX_STEP_FRAMES} (0 means 1); step longer runs in several calls or Resume"
        ))),
    }
}

/// Step a paused loop by `frames` frames.
pub async fn step(commands: &mpsc::Sender<Command>, frames: u32) -> Result<pb::LoopState, Status> {
    let frames = step_frames(frames)?;
    let (tx, rx) = oneshot::channel();
    match ask(commands, Command::Step(frames, tx), rx, "Step").await? {
        Ok(state) => Ok(to_pb(state)),
        Err(StepRefused) => Err(Status::failed_precondition(
            "Step advances a paused frame loop, and this one is running (or already stepping): call Pause first",
        )),
    }
}

/// The Configure a Restart is: the seed alone under a mask, or nothing (the same scene again).
pub fn restart_request(seed: Option<u64>) -> pb::ConfigureRequest {
    let Some(seed) = seed else {
        return pb::ConfigureRequest::default();
    };
    let mut request = pb::ConfigureRequest {
        config: Some(pb::SceneConfig {
            seed,
            ..Default::default()
        }),
        update_mask: Some(Default::default()),
    };
    if let Some(mask) = request.update_mask.as_mut() {
        mask.paths.push("seed".to_owned());
    }
    request
}

/// Body `body`'s pairs in the latest frame; `bodies` is the scene's body count, for the check.
pub async fn inspect(
    commands: &mpsc::Sender<Command>,
    body: u32,
    bodies: u32,
) -> Result<pb::BodyInspection, Status> {
    let out_of_range = |bodies: u32| {
        Status::invalid_argument(format!(
            "InspectBodyRequest.body = {body}: the scene has {bodies} bodies, numbered 0..={}",
            bodies.saturating_sub(1)
        ))
    };
    if body >= bodies {
        return Err(out_of_range(bodies));
    }
    let (tx, rx) = oneshot::channel();
    let found = ask(commands, Command::Inspect(body, tx), rx, "InspectBody").await?;
    // The scene may have changed between the check and the loop's answer.
    if body >= found.bodies {
        return Err(out_of_range(found.bodies));
    }
    Ok(pb::BodyInspection {
        frame_index: found.frame_index,
        body,
        pairs: found.pairs,
        pairs_total: found.pairs_total,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn step_frames_are_checked_and_named() {
        assert_eq!(step_frames(0).ok(), Some(1));
        assert_eq!(step_frames(7).ok(), Some(7));
        assert_eq!(step_frames(MAX_STEP_FRAMES).ok(), Some(MAX_STEP_FRAMES));
        let e = step_frames(MAX_STEP_FRAMES + 1).expect_err("over the limit");
        assert_eq!(e.code(), tonic::Code::InvalidArgument);
        assert!(
            e.message().starts_with("StepRequest.frames = 601"),
            "{}",
            e.message()
        );
    }

    #[test]
    fn restart_is_a_configure_of_the_seed_or_of_nothing() {
        let r = restart_request(Some(0));
        assert_eq!(r.config.map(|c| c.seed), Some(0));
        assert_eq!(
            r.update_mask.map(|m| m.paths),
            Some(vec!["seed".to_owned()])
        );
        assert_eq!(restart_request(None), pb::ConfigureRequest::default());
    }
}
