//! The results directory: one CSV per participant and session, and a JSON header beside it.
//!
//! A session's files are created when it starts (never over an existing file: a second session
//! with the same participant and label is refused, so nothing stored is overwritten) and each
//! trial is appended and synced to disk as it arrives, so a closed tab or a crashed browser loses
//! at most the trial in flight. The header holds the design, the display geometry and the
//! software's version; it is rewritten (to a temporary file, then renamed over) only to add how
//! the session ended.

use std::collections::HashMap;
use std::fs::{File, OpenOptions};
use std::hash::{BuildHasher, Hasher};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::{Instant, SystemTime, UNIX_EPOCH};

use foveal_engine::Display;
use serde_json::{Value, json};

use super::design::{Design, Designs, is_plain_name};
use super::fields::{FieldError, Fields};
use super::trial::{COLUMNS, TrialRecord};

/// Sessions open at once; a new one beyond them first closes those idle for an hour.
pub const MAX_OPEN_SESSIONS: usize = 64;

/// A session idle this long may be closed to make room for a new one.
const IDLE_SESSION: std::time::Duration = std::time::Duration::from_secs(3600);

/// Longest participant id and session label.
pub const MAX_ID: usize = 32;

/// What the page sends to start a session (JSON).
#[derive(Debug, Clone, PartialEq)]
pub struct SessionRequest {
    /// Opaque participant id (letters, digits, `-`, `_`): never a name.
    pub participant: String,
    /// Session label (`1`, `2`, `pilot`).
    pub session: String,
    /// The design's name.
    pub design: String,
    /// The page's display, as measured and calibrated.
    pub display: BrowserDisplay,
}

impl SessionRequest {
    /// The request in a JSON body, every field read by name.
    pub fn from_json(bytes: &[u8]) -> Result<Self, FieldError> {
        const NUM: &str = "a number";
        let mut f = Fields::parse(bytes)?;
        let mut d = f.object("display")?;
        let display = BrowserDisplay {
            px_per_cm: d.req("px_per_cm", NUM)?,
            px_per_cm_source: d.req("px_per_cm_source", "`calibration` or `display-flags`")?,
            viewing_distance_cm: d.req("viewing_distance_cm", NUM)?,
            window_width_px: d.req("window_width_px", NUM)?,
            window_height_px: d.req("window_height_px", NUM)?,
            device_pixel_ratio: d.req("device_pixel_ratio", NUM)?,
            refresh_ms: d.req("refresh_ms", NUM)?,
        };
        d.done()?;
        let request = Self {
            participant: f.req("participant", "an opaque id")?,
            session: f.req("session", "a session label")?,
            design: f.req("design", "a design name")?,
            display,
        };
        f.done()?;
        Ok(request)
    }
}

impl From<FieldError> for Refusal {
    fn from(e: FieldError) -> Self {
        Self::field(400, &e.field, e.to_string())
    }
}

/// The display as the page found it.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct BrowserDisplay {
    /// CSS pixels per centimetre the page draws with.
    pub px_per_cm: f64,
    /// Where that came from: `calibration` (the card matched on screen) or `display-flags`
    /// (the server's `--display-*` flags and the browser's device pixel ratio).
    pub px_per_cm_source: String,
    /// Eye to screen (cm) the page computes angles with.
    pub viewing_distance_cm: f64,
    /// The page's size (CSS pixels).
    pub window_width_px: f64,
    /// See `window_width_px`.
    pub window_height_px: f64,
    /// Device pixels per CSS pixel.
    pub device_pixel_ratio: f64,
    /// The refresh period measured before the first trial (ms).
    pub refresh_ms: f64,
}

/// A refused request: the HTTP status, the field at fault (if one) and why.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{message}")]
pub struct Refusal {
    /// The HTTP status to answer with.
    pub status: u16,
    /// The field at fault.
    pub field: Option<String>,
    /// The message.
    pub message: String,
}

impl Refusal {
    /// A refusal with `status`, naming `field`.
    pub fn field(status: u16, field: &str, message: impl Into<String>) -> Self {
        Self {
            status,
            field: Some(field.to_owned()),
            message: message.into(),
        }
    }

    /// A refusal with `status` about no one field.
    pub fn plain(status: u16, message: impl Into<String>) -> Self {
        Self {
            status,
            field: None,
            message: message.into(),
        }
    }
}

/// One open session.
#[derive(Debug)]
struct Session {
    participant: String,
    label: String,
    design: Design,
    csv: File,
    csv_path: PathBuf,
    header_path: PathBuf,
    header: Value,
    /// The next trial number expected.
    next: u32,
    /// Rows the session may still take: the design's trials plus every block's repeats.
    room: usize,
    last_used: Instant,
}

/// Every open session, and where files go.
#[derive(Debug)]
pub struct Store {
    dir: PathBuf,
    designs: Designs,
    display: Display,
    sessions: Mutex<HashMap<String, Session>>,
    counter: AtomicU64,
    seed: std::collections::hash_map::RandomState,
}

/// What a started session is told.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Started {
    /// The session's id, for its trials.
    pub id: String,
    /// The CSV's path.
    pub csv: String,
}

impl Store {
    /// A store writing under `dir` (created when the first session starts), with designs from
    /// `designs`, on a display described by the server's flags.
    pub fn new(dir: PathBuf, designs: Designs, display: Display) -> Self {
        Self {
            dir,
            designs,
            display,
            sessions: Mutex::new(HashMap::new()),
            counter: AtomicU64::new(0),
            seed: std::collections::hash_map::RandomState::new(),
        }
    }

    /// The results directory.
    pub fn dir(&self) -> &Path {
        &self.dir
    }

    /// The designs.
    pub fn designs(&self) -> &Designs {
        &self.designs
    }

    /// The display the server's flags describe.
    pub fn display(&self) -> Display {
        self.display
    }

    fn sessions(&self) -> std::sync::MutexGuard<'_, HashMap<String, Session>> {
        // A panic while holding the lock leaves the map as it was between two whole operations.
        self.sessions
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
    }

    /// An id nobody can guess from the ones before it.
    fn new_id(&self) -> String {
        let mut h = self.seed.build_hasher();
        h.write_u64(self.counter.fetch_add(1, Ordering::Relaxed));
        h.write_u128(
            SystemTime::now()
                .duration_since(UNIX_EPOCH)
                .map_or(0, |d| d.as_nanos()),
        );
        format!("{:016x}", h.finish())
    }

    /// Start a session: check the request, create its CSV (header row) and JSON header.
    pub fn start(&self, request: &SessionRequest) -> Result<Started, Refusal> {
        for (field, v) in [
            ("participant", &request.participant),
            ("session", &request.session),
        ] {
            if !is_plain_name(v, MAX_ID) {
                return Err(Refusal::field(
                    400,
                    field,
                    format!(
                        "`{field}` must be 1 to {MAX_ID} ASCII letters, digits, `-` or `_`: an opaque id, never a name or an e-mail address"
                    ),
                ));
            }
        }
        let design = self
            .designs
            .load(&request.design)
            .map_err(|e| Refusal::field(400, "design", e.to_string()))?;
        check_display(&request.display)?;
        let mut sessions = self.sessions();
        if sessions.len() >= MAX_OPEN_SESSIONS {
            sessions.retain(|_, s| s.last_used.elapsed() < IDLE_SESSION);
        }
        if sessions.len() >= MAX_OPEN_SESSIONS {
            return Err(Refusal::plain(
                503,
                format!(
                    "{MAX_OPEN_SESSIONS} sessions are open: finish one, or retry in an hour when idle ones close"
                ),
            ));
        }
        std::fs::create_dir_all(&self.dir).map_err(|e| {
            Refusal::plain(
                500,
                format!("creating the results directory {}: {e}", self.dir.display()),
            )
        })?;
        let stem = format!("{}_{}", request.participant, request.session);
        let csv_path = self.dir.join(format!("{stem}.csv"));
        let header_path = self.dir.join(format!("{stem}.json"));
        let mut csv = match OpenOptions::new()
            .append(true)
            .create_new(true)
            .open(&csv_path)
        {
            Ok(f) => f,
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => {
                return Err(Refusal::field(
                    409,
                    "session",
                    format!(
                        "participant `{}` already has a session `{}` ({}): choose another session label; stored results are never overwritten",
                        request.participant,
                        request.session,
                        csv_path.display()
                    ),
                ));
            }
            Err(e) => {
                return Err(Refusal::plain(
                    500,
                    format!("creating {}: {e}", csv_path.display()),
                ));
            }
        };
        let header = json!({
            "format": "foveal-psych-results",
            "format_version": 1,
            "software": { "name": "foveal-server", "version": env!("CARGO_PKG_VERSION") },
            "started_utc": utc_now(),
            "finished_utc": null,
            "participant": request.participant,
            "session": request.session,
            "results": csv_path.file_name().map(|n| n.to_string_lossy().into_owned()),
            "columns": COLUMNS,
            "design": design,
            "display": {
                "configured": {
                    "width_px": self.display.width_px,
                    "height_px": self.display.height_px,
                    "diagonal_in": self.display.diagonal_in,
                    "viewing_distance_cm": self.display.viewing_distance_cm,
                },
                "browser": request.display,
            },
            "trials_stored": 0,
        });
        let written = csv
            .write_all(format!("{}\n", COLUMNS.join(",")).as_bytes())
            .and_then(|()| csv.sync_data())
            .and_then(|()| write_header(&header_path, &header));
        if let Err(e) = written {
            // Nothing of this session is stored yet: leave no half-made files behind.
            let _ = std::fs::remove_file(&csv_path);
            return Err(Refusal::plain(
                500,
                format!("writing {}: {e}", csv_path.display()),
            ));
        }
        let id = self.new_id();
        let room = design.trials() + (design.blocks * design.timing.max_repeats_per_block) as usize;
        tracing::info!(session = %id, csv = %csv_path.display(), design = %design.name, "psych session started");
        sessions.insert(
            id.clone(),
            Session {
                participant: request.participant.clone(),
                label: request.session.clone(),
                design,
                csv,
                csv_path: csv_path.clone(),
                header_path,
                header,
                next: 1,
                room,
                last_used: Instant::now(),
            },
        );
        Ok(Started {
            id,
            csv: csv_path.display().to_string(),
        })
    }

    /// Append one trial to session `id`'s CSV and sync it; the trial number it took.
    pub fn append(&self, id: &str, trial: &TrialRecord) -> Result<u32, Refusal> {
        let mut sessions = self.sessions();
        let session = sessions.get_mut(id).ok_or_else(|| unknown(id))?;
        trial.validate(&session.design, session.next).map_err(|e| {
            Refusal::field(
                if e.field == "trial" { 409 } else { 400 },
                &e.field,
                e.to_string(),
            )
        })?;
        if session.room == 0 {
            return Err(Refusal::field(
                409,
                "trial",
                "the session already holds every trial its design allows (its trials and every block's repeats)",
            ));
        }
        let row = trial.row(&session.participant, &session.label, &session.design.name);
        session
            .csv
            .write_all(row.as_bytes())
            .and_then(|()| session.csv.sync_data())
            .map_err(|e| {
                Refusal::plain(
                    500,
                    format!("appending to {}: {e}", session.csv_path.display()),
                )
            })?;
        session.next += 1;
        session.room -= 1;
        session.last_used = Instant::now();
        Ok(trial.trial)
    }

    /// Close session `id`: record in its header how it ended and how many trials it stored.
    pub fn finish(&self, id: &str, completed: bool) -> Result<u32, Refusal> {
        let mut sessions = self.sessions();
        let session = sessions.remove(id).ok_or_else(|| unknown(id))?;
        let stored = session.next - 1;
        let mut header = session.header;
        header["finished_utc"] = json!(utc_now());
        header["completed"] = json!(completed);
        header["trials_stored"] = json!(stored);
        write_header(&session.header_path, &header).map_err(|e| {
            Refusal::plain(
                500,
                format!("writing {}: {e}", session.header_path.display()),
            )
        })?;
        Ok(stored)
    }
}

fn unknown(id: &str) -> Refusal {
    Refusal::field(
        404,
        "session",
        format!(
            "no open session `{}` (finished, closed after an hour idle, or the server restarted): start a new session",
            id.chars().take(40).collect::<String>()
        ),
    )
}

fn check_display(d: &BrowserDisplay) -> Result<(), Refusal> {
    let range = |field: &str, v: f64, lo: f64, hi: f64| {
        if v.is_finite() && (lo..=hi).contains(&v) {
            Ok(())
        } else {
            Err(Refusal::field(
                400,
                field,
                format!("`{field}` = {v}: must be within {lo}..={hi}"),
            ))
        }
    };
    range("display.px_per_cm", d.px_per_cm, 5.0, 500.0)?;
    if !matches!(d.px_per_cm_source.as_str(), "calibration" | "display-flags") {
        return Err(Refusal::field(
            400,
            "display.px_per_cm_source",
            "`display.px_per_cm_source` must be `calibration` or `display-flags`",
        ));
    }
    range(
        "display.viewing_distance_cm",
        d.viewing_distance_cm,
        1.0,
        10_000.0,
    )?;
    range("display.window_width_px", d.window_width_px, 1.0, 100_000.0)?;
    range(
        "display.window_height_px",
        d.window_height_px,
        1.0,
        100_000.0,
    )?;
    range(
        "display.device_pixel_ratio",
        d.device_pixel_ratio,
        0.1,
        16.0,
    )?;
    range("display.refresh_ms", d.refresh_ms, 0.5, 1000.0)
}

/// Write `header` to `path` through a temporary file renamed over it: a reader never sees half.
fn write_header(path: &Path, header: &Value) -> std::io::Result<()> {
    let tmp = path.with_extension("json.tmp");
    let text = serde_json::to_string_pretty(header).map_err(std::io::Error::other)?;
    let mut f = File::create(&tmp)?;
    f.write_all(text.as_bytes())?;
    f.write_all(b"\n")?;
    f.sync_data()?;
    std::fs::rename(&tmp, path)
}

/// Now, as `2026-12-08T10:11:12Z`.
fn utc_now() -> String {
    let secs = SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .map_or(0, |d| d.as_secs());
    let days = (secs / 86_400) as i64;
    let rem = secs % 86_400;
    // Howard Hinnant's civil_from_days.
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = doy - (153 * mp + 2) / 5 + 1;
    let month = if mp < 10 { mp + 3 } else { mp - 9 };
    let year = yoe + era * 400 + i64::from(month <= 2);
    format!(
        "{year:04}-{month:02}-{day:02}T{:02}:{:02}:{:02}Z",
        rem / 3600,
        rem % 3600 / 60,
        rem % 60
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn utc_dates_are_civil() {
        let s = utc_now();
        assert_eq!(s.len(), 20, "{s}");
        assert!(s.starts_with("20") && s.ends_with('Z'), "{s}");
    }
}
