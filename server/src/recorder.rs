//! `--record FILE`: the session written to disk as it happens (format in `foveal-session`).
//!
//! A dedicated writer thread owns the file; the frame loop and the gaze handlers hand it records
//! through a bounded channel and never wait: when the writer has fallen behind (a slow disk) the
//! record is dropped and counted, the first drop is logged, and the count goes into the file's
//! trailer and the final log line. A frame is about now; a stalled frame to keep a log complete
//! would change what is being recorded.
//!
//! [`Recorder::finish`] (called on every way out of [`crate::run`], Ctrl-C included, and by
//! `Drop` as a last resort) hands the writer its last message, waits for it to write the
//! trailer and flush, and logs what was kept.

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::mpsc::{self, SyncSender, TrySendError};
use std::sync::{Mutex, PoisonError};
use std::thread::JoinHandle;

use foveal_engine::{FrameReport, SimConfig};
use foveal_gaze::{Eye, GazeSample};
use foveal_session::{
    FrameRecord, GazeRecord, GazeSettings, Header, Record, SceneRecord, ServerSettings,
    SessionError, SessionWriter, Trailer,
};

use crate::config::ServerConfig;
use crate::error::ServerError;
use crate::fixation_cell::ResolvedFixation;

/// Records the channel holds before the writer counts as behind: about four seconds of a
/// 60 Hz loop fed by a 1 kHz tracker, far more than a healthy disk ever needs.
pub const CHANNEL_RECORDS: usize = 4096;

enum Msg {
    Record(Record),
    /// Write the trailer with this many drops and stop.
    Finish(u64),
}

/// The handle the frame loop and the handlers record through.
#[derive(Debug)]
pub struct Recorder {
    path: PathBuf,
    tx: SyncSender<Msg>,
    dropped: AtomicU64,
    warned: AtomicBool,
    thread: Mutex<Option<JoinHandle<Result<Trailer, SessionError>>>>,
    /// The trailer, once finished.
    trailer: Mutex<Option<Trailer>>,
}

impl std::fmt::Debug for Msg {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Record(_) => f.write_str("Record"),
            Self::Finish(d) => write!(f, "Finish({d})"),
        }
    }
}

/// The session header for a server starting with `config`.
pub fn header(config: &ServerConfig) -> Header {
    Header::new(
        config.sim.clone(),
        ServerSettings {
            frame_rate_hz: config.frame_rate_hz,
            gaze_max_age_s: config.gaze_max_age.as_secs_f64(),
            gaze_processing: GazeSettings::from(&config.gaze_processing),
        },
    )
}

impl Recorder {
    /// Create `path`, write the header, and start the writer thread. Refuses (naming the flag
    /// and the path) when the file cannot be created or take the header.
    pub fn start(path: &Path, header: &Header) -> Result<Self, ServerError> {
        let fail = |source: SessionError| ServerError::Record {
            path: path.display().to_string(),
            source,
        };
        let file = File::create(path).map_err(|e| fail(SessionError::Io(e)))?;
        let recorder =
            Self::over(BufWriter::new(file), path, header, CHANNEL_RECORDS).map_err(fail)?;
        tracing::info!(path = %path.display(), "recording the session");
        Ok(recorder)
    }

    /// Write the header to `out`, then records from a writer thread fed by a channel of
    /// `capacity` records; `path` names it in the log.
    fn over(
        out: impl Write + Send + 'static,
        path: &Path,
        header: &Header,
        capacity: usize,
    ) -> Result<Self, SessionError> {
        let writer = SessionWriter::new(out, header)?;
        let (tx, rx) = mpsc::sync_channel(capacity);
        let thread = std::thread::Builder::new()
            .name("foveal-recorder".into())
            .spawn(move || write_all(writer, &rx))?;
        Ok(Self {
            path: path.to_owned(),
            tx,
            dropped: AtomicU64::new(0),
            warned: AtomicBool::new(false),
            thread: Mutex::new(Some(thread)),
            trailer: Mutex::new(None),
        })
    }

    fn send(&self, record: Record) {
        match self.tx.try_send(Msg::Record(record)) {
            Ok(()) => {}
            Err(TrySendError::Full(_)) => {
                self.dropped.fetch_add(1, Ordering::Relaxed);
                if !self.warned.swap(true, Ordering::Relaxed) {
                    tracing::warn!(
                        path = %self.path.display(),
                        capacity = CHANNEL_RECORDS,
                        "the session writer has fallen behind: records are being dropped (counted in the trailer)"
                    );
                }
            }
            // The writer has finished (the server is stopping): nothing after the end is kept.
            Err(TrySendError::Disconnected(_)) => {}
        }
    }

    /// A sample handed to the gaze processing at `received_s` on the processing's clock.
    pub fn gaze(&self, sample: &GazeSample, received_s: f64, source: &str) {
        let finite = |v: f64| Some(v).filter(|v| v.is_finite());
        self.send(Record::Gaze(GazeRecord {
            received_s,
            source: source.to_owned(),
            tracker_time_s: sample.t_s,
            x: finite(sample.x),
            y: finite(sample.y),
            validity: sample.validity,
            eye: eye_name(sample.eye).to_owned(),
            fixation: sample.fixation,
        }));
    }

    /// A completed frame: its protocol index, start time on the gaze clock, what it was handed.
    pub fn frame(&self, index: u64, t_s: f64, resolved: &ResolvedFixation, report: &FrameReport) {
        self.send(Record::Frame(Box::new(FrameRecord {
            index,
            t_s,
            fixation: resolved.fixation,
            fixation_source: resolved.source.name().to_owned(),
            report: report.clone(),
        })));
    }

    /// A scene swap effective from `first_frame`.
    pub fn scene(&self, first_frame: u64, frame_rate_hz: f64, sim: &SimConfig) {
        self.send(Record::Scene(Box::new(SceneRecord {
            first_frame,
            frame_rate_hz,
            sim: sim.clone(),
        })));
    }

    /// Write the trailer, flush and close the file (waiting for the writer to drain), and log
    /// what was kept. Later calls, and records sent after, do nothing.
    pub fn finish(&self) {
        if let Some(t) = self.finish_inner() {
            *self.trailer.lock().unwrap_or_else(PoisonError::into_inner) = Some(t);
        }
    }

    /// The trailer written by [`Self::finish`] (None before it, or if writing failed).
    #[cfg(test)]
    fn trailer(&self) -> Option<Trailer> {
        *self.trailer.lock().unwrap_or_else(PoisonError::into_inner)
    }

    fn finish_inner(&self) -> Option<Trailer> {
        let thread = self
            .thread
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .take()?;
        let dropped = self.dropped.load(Ordering::Relaxed);
        // Blocking on purpose: the frame loop has stopped, and the file must be complete.
        // Err: the writer thread is gone; joining says why.
        let _ = self.tx.send(Msg::Finish(dropped));
        let path = self.path.display();
        match thread.join() {
            Ok(Ok(t)) => {
                if t.dropped > 0 {
                    tracing::warn!(
                        %path,
                        frames = t.frames,
                        gaze_samples = t.gaze_samples,
                        scenes = t.scenes,
                        dropped = t.dropped,
                        "session recorded with records dropped (the writer fell behind)"
                    );
                } else {
                    tracing::info!(
                        %path,
                        frames = t.frames,
                        gaze_samples = t.gaze_samples,
                        scenes = t.scenes,
                        dropped = 0,
                        "session recorded"
                    );
                }
                Some(t)
            }
            Ok(Err(e)) => {
                tracing::error!(%path, error = %e, "recording the session failed");
                None
            }
            Err(_) => {
                tracing::error!(%path, "the session writer thread panicked");
                None
            }
        }
    }
}

impl Drop for Recorder {
    fn drop(&mut self) {
        self.finish();
    }
}

/// The writer thread: write records until told to finish. After a write error the rest is
/// drained unwritten (senders never block either way) and the error is returned at the end.
fn write_all<W: Write>(
    mut writer: SessionWriter<W>,
    rx: &mpsc::Receiver<Msg>,
) -> Result<Trailer, SessionError> {
    let mut failed: Option<SessionError> = None;
    let mut lost = 0u64;
    // Ends on Finish, or when every sender is gone (cannot happen before Finish: the Recorder
    // holds one and finishes on drop).
    let dropped = loop {
        match rx.recv() {
            Ok(Msg::Record(r)) => {
                if failed.is_some() {
                    lost += 1;
                } else if let Err(e) = writer.write(&r) {
                    tracing::error!(error = %e, "writing the session failed; later records are lost");
                    failed = Some(e);
                }
            }
            Ok(Msg::Finish(dropped)) => break dropped,
            Err(_) => break 0,
        }
    };
    match failed {
        Some(e) => {
            tracing::error!(lost, "session records not written after the failure");
            Err(e)
        }
        None => writer.finish(dropped).map(|(_, t)| t),
    }
}

fn eye_name(eye: Eye) -> &'static str {
    match eye {
        Eye::Unspecified => "unspecified",
        Eye::Left => "left",
        Eye::Right => "right",
        Eye::Binocular => "binocular",
    }
}

#[cfg(test)]
mod tests {
    use std::sync::Arc;
    use std::sync::mpsc::{Receiver, Sender};

    use foveal_engine::Fixation;
    use foveal_gaze::online::Track;

    use super::*;
    use crate::fixation_cell::FixationSource;

    /// A shared byte sink whose writes wait, once `hold` is set, until `release` says go; it
    /// tells `entered` when a write starts waiting. A disk that has stalled, on demand.
    #[derive(Clone)]
    struct Stall {
        bytes: Arc<Mutex<Vec<u8>>>,
        hold: Arc<AtomicBool>,
        entered: Sender<()>,
        release: Arc<Mutex<Receiver<()>>>,
    }

    impl Write for Stall {
        fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
            if self.hold.swap(false, Ordering::SeqCst) {
                let _ = self.entered.send(());
                let _ = self
                    .release
                    .lock()
                    .unwrap_or_else(PoisonError::into_inner)
                    .recv();
            }
            self.bytes
                .lock()
                .unwrap_or_else(PoisonError::into_inner)
                .extend_from_slice(buf);
            Ok(buf.len())
        }

        fn flush(&mut self) -> std::io::Result<()> {
            Ok(())
        }
    }

    fn resolved() -> ResolvedFixation {
        ResolvedFixation {
            fixation: Fixation::at(0.25, 0.75),
            source: FixationSource::Gaze,
            raw: None,
            track: Track::Raw,
            widen_deg: 0.0,
        }
    }

    #[test]
    fn the_header_says_which_truth_the_frames_were_decided_by() {
        let (entered, _) = mpsc::channel();
        let (_, release) = mpsc::channel();
        let sink = Stall {
            bytes: Arc::default(),
            hold: Arc::default(),
            entered,
            release: Arc::new(Mutex::new(release)),
        };
        let mut config = ServerConfig::default();
        config.sim.scene.truth = foveal_engine::Truth::LeafSpheres;
        let rec = Recorder::over(sink.clone(), Path::new("test"), &header(&config), 8)
            .expect("header written");
        rec.finish();
        let bytes = sink
            .bytes
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .clone();
        let first = bytes.split(|&b| b == b'\n').next().expect("a header line");
        let first = String::from_utf8_lossy(first);
        assert!(first.contains(r#""truth":"leaf-spheres""#), "{first}");
        let s = foveal_session::Session::read(bytes.as_slice()).expect("a complete session");
        assert_eq!(s.header.sim.scene.truth, foveal_engine::Truth::LeafSpheres);
    }

    #[test]
    fn a_stalled_writer_drops_and_counts_records_instead_of_blocking() {
        let (entered_tx, entered) = mpsc::channel();
        let (release, release_rx) = mpsc::channel();
        let sink = Stall {
            bytes: Arc::default(),
            hold: Arc::default(),
            entered: entered_tx,
            release: Arc::new(Mutex::new(release_rx)),
        };
        let header = header(&ServerConfig::default());
        let capacity = 8;
        let rec = Recorder::over(sink.clone(), Path::new("test"), &header, capacity)
            .expect("header written");
        // The first frame reaches the writer, whose disk then stalls.
        sink.hold.store(true, Ordering::SeqCst);
        let report = FrameReport::default();
        rec.frame(0, 0.0, &resolved(), &report);
        entered
            .recv_timeout(std::time::Duration::from_secs(10))
            .expect("the writer took the first record");
        // The channel fills, then every further record is dropped at once, not waited for.
        let started = std::time::Instant::now();
        for i in 1..=(capacity as u64 + 5) {
            rec.frame(i, 0.0, &resolved(), &report);
        }
        assert!(started.elapsed() < std::time::Duration::from_secs(1));
        assert_eq!(rec.dropped.load(Ordering::Relaxed), 5);
        release.send(()).expect("writer waiting");
        rec.finish();
        let t = rec.trailer().expect("finished");
        assert_eq!((t.frames, t.dropped), (1 + capacity as u64, 5));
        // And the file says so.
        let bytes = sink
            .bytes
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .clone();
        let s = foveal_session::Session::read(bytes.as_slice()).expect("a complete session");
        assert_eq!(s.trailer.dropped, 5);
        assert_eq!(s.frames.len(), 1 + capacity);
        // Records after the end are not kept, and finishing twice is harmless.
        rec.frame(99, 0.0, &resolved(), &report);
        rec.finish();
        assert_eq!(rec.trailer(), Some(t));
    }
}
