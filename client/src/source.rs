//! Sample sources, each delivered as a channel of [`SourceItem`]s.
//!
//! Every source ends up as the same bounded channel, so that [`crate::bridge::forward`] is the
//! one loop for scripts, replays and live trackers alike. Blocking readers (files, stdin) run on
//! a plain OS thread rather than `spawn_blocking`: a thread stuck in a read of an idle stdin
//! must not keep the runtime from shutting down. The bounded channel gives back-pressure, so a
//! replay reads no faster than it is sent.
//!
//! A [`SourceError::Parse`] is one bad line: the source goes on. A [`SourceError::Io`] ends it.

use std::fs::File;
use std::io::{self, BufRead, BufReader, Cursor, Read};
use std::path::Path;
use std::time::Duration;

use thiserror::Error;
use tokio::io::{AsyncBufReadExt, AsyncReadExt, AsyncWriteExt, BufReader as AsyncBufReader};
use tokio::net::TcpStream;
use tokio::sync::mpsc;
use tracing::{debug, info, warn};

use crate::gaze::asc::AscReader;
use crate::gaze::csv::CsvGazeReader;
use crate::gaze::opengaze::{self, OpenGazeMessage};
use crate::gaze::script::ScriptedGaze;
use crate::gaze::{Binocular, Eye, GazeSample, ParseError, ScreenPx};

/// What a source gives: a sample or a reason why there is none.
pub type SourceItem = Result<GazeSample, SourceError>;

/// Why a source gave no sample.
#[derive(Debug, Error)]
pub enum SourceError {
    /// One line could not be parsed; the source goes on with the next.
    #[error(transparent)]
    Parse(ParseError),
    /// The source failed and ends (unreadable input, tracker unreachable).
    #[error("{what}: {source}")]
    Io {
        /// What was being done.
        what: String,
        /// The I/O error.
        #[source]
        source: io::Error,
    },
}

impl From<ParseError> for SourceError {
    /// A read error inside a parser ends the source, so it becomes [`SourceError::Io`].
    fn from(err: ParseError) -> Self {
        match err {
            ParseError::Io { line, source } => Self::Io {
                what: format!("read line {line}"),
                source,
            },
            other => Self::Parse(other),
        }
    }
}

/// Items a source may queue ahead of the sender.
pub const CHANNEL_CAPACITY: usize = 1024;

/// Runs `items` on its own thread and delivers them through a channel; the thread ends when
/// the iterator does or when the receiver is dropped.
pub fn spawn_iter<I>(name: &str, items: I) -> mpsc::Receiver<SourceItem>
where
    I: Iterator<Item = SourceItem> + Send + 'static,
{
    spawn_with(name, move || items)
}

/// As [`spawn_iter`], with the iterator made on the thread (for readers that cannot move
/// between threads, such as a locked stdin).
pub fn spawn_with<F, I>(name: &str, make: F) -> mpsc::Receiver<SourceItem>
where
    F: FnOnce() -> I + Send + 'static,
    I: Iterator<Item = SourceItem>,
{
    let (tx, rx) = mpsc::channel(CHANNEL_CAPACITY);
    let spawned = std::thread::Builder::new()
        .name(format!("source-{name}"))
        .spawn(move || {
            for item in make() {
                if tx.blocking_send(item).is_err() {
                    break;
                }
            }
        });
    if let Err(err) = spawned {
        // Dropping the sender closes the channel; forward() then reports this source as empty.
        warn!(error = %err, "cannot start the {name} reader thread");
    }
    rx
}

/// A scripted gaze stream as a source (it never fails; it ends only if the script does).
pub fn script(gaze: ScriptedGaze) -> mpsc::Receiver<SourceItem> {
    spawn_iter("script", gaze.map(Ok))
}

/// Format of a gaze recording.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RecordingFormat {
    /// CSV (pixel or normalised layout, see [`crate::gaze::csv`]).
    Csv,
    /// EyeLink ASC.
    Asc,
}

/// Bytes looked at to tell CSV from ASC when the file name does not say.
const SNIFF_BYTES: usize = 16 * 1024;

/// The format of a recording: from the extension (`.asc`, `.csv`) when it has one of those,
/// else from its first bytes (see [`sniff_format`]).
#[must_use]
pub fn detect_format(path: Option<&Path>, head: &[u8]) -> RecordingFormat {
    let extension = path
        .and_then(Path::extension)
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    match extension.as_deref() {
        Some("asc") => RecordingFormat::Asc,
        Some("csv") => RecordingFormat::Csv,
        _ => sniff_format(head),
    }
}

/// The format of a recording from its first bytes: ASC when the first meaningful line is an
/// EyeLink header (`**`), message or event keyword, or a whitespace-separated sample line; CSV
/// otherwise (a `t_s,...` header, or anything else, which the CSV reader then explains).
#[must_use]
pub fn sniff_format(head: &[u8]) -> RecordingFormat {
    const ASC_KEYWORDS: [&str; 12] = [
        "MSG",
        "SAMPLES",
        "EVENTS",
        "START",
        "END",
        "PRESCALER",
        "VPRESCALER",
        "PUPIL",
        "SFIX",
        "EFIX",
        "SSACC",
        "INPUT",
    ];
    let text = String::from_utf8_lossy(head);
    for line in text.lines().map(str::trim) {
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        if line.starts_with("**") {
            return RecordingFormat::Asc;
        }
        if line.contains(',') {
            return RecordingFormat::Csv;
        }
        let first = line.split_whitespace().next().unwrap_or_default();
        if ASC_KEYWORDS.contains(&first)
            || (first.bytes().all(|b| b.is_ascii_digit()) && line.contains(char::is_whitespace))
        {
            return RecordingFormat::Asc;
        }
        return RecordingFormat::Csv;
    }
    RecordingFormat::Csv
}

/// Reads up to [`SNIFF_BYTES`] of `reader` and gives them back chained in front of the rest.
fn peek<R: Read>(mut reader: R) -> io::Result<(Vec<u8>, impl Read)> {
    let mut head = Vec::with_capacity(SNIFF_BYTES);
    Read::take(&mut reader, SNIFF_BYTES as u64).read_to_end(&mut head)?;
    Ok((head.clone(), Read::chain(Cursor::new(head), reader)))
}

/// How a recording is read: its format (detected when `None`), the screen for pixel gaze (wins
/// over a size declared in the file) and what becomes of a binocular recording's two eyes.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct ReadOptions {
    /// CSV or ASC; `None` detects it from the extension or the content.
    pub format: Option<RecordingFormat>,
    /// Screen size for pixel gaze.
    pub screen: Option<ScreenPx>,
    /// The eyes of a binocular recording (default: their mean).
    pub eyes: Binocular,
}

/// Opens a recording, detects its format (unless `options` say) and reads it on a thread.
///
/// # Errors
/// The file cannot be opened or read.
pub fn recording(
    path: &Path,
    options: ReadOptions,
) -> io::Result<(RecordingFormat, mpsc::Receiver<SourceItem>)> {
    let file = File::open(path)?;
    let (head, reader) = peek(file)?;
    let format = options
        .format
        .unwrap_or_else(|| detect_format(Some(path), &head));
    let name = match format {
        RecordingFormat::Csv => "csv",
        RecordingFormat::Asc => "asc",
    };
    let reader = sample_reader(format, BufReader::new(reader), &options);
    Ok((
        format,
        spawn_iter(name, reader.map(|r| r.map_err(SourceError::from))),
    ))
}

/// Reads a recording in `format` from any reader, on a thread; `screen`, when given, converts
/// pixel gaze and wins over a size declared in the input.
pub fn reader_source<R>(
    format: RecordingFormat,
    reader: R,
    screen: Option<ScreenPx>,
) -> mpsc::Receiver<SourceItem>
where
    R: BufRead + Send + 'static,
{
    let options = ReadOptions {
        format: Some(format),
        screen,
        ..ReadOptions::default()
    };
    spawn_iter(
        "recording",
        sample_reader(format, reader, &options).map(|r| r.map_err(SourceError::from)),
    )
}

/// A reader of either format as one iterator, set up by `options`; it also says which eyes the
/// recording holds once its header has been read.
enum SampleReader<R> {
    Csv(CsvGazeReader<R>),
    Asc(AscReader<R>),
}

impl<R: BufRead> Iterator for SampleReader<R> {
    type Item = Result<GazeSample, ParseError>;

    fn next(&mut self) -> Option<Self::Item> {
        match self {
            Self::Csv(r) => r.next(),
            Self::Asc(r) => r.next(),
        }
    }
}

impl<R: BufRead> SampleReader<R> {
    /// Whether the recording holds both eyes, as far as it has been read.
    fn binocular(&self) -> bool {
        match self {
            Self::Csv(r) => r.is_binocular() == Some(true),
            Self::Asc(r) => r.eye() == Eye::Binocular,
        }
    }
}

fn sample_reader<R: BufRead>(
    format: RecordingFormat,
    reader: R,
    options: &ReadOptions,
) -> SampleReader<R> {
    match format {
        RecordingFormat::Csv => {
            let mut reader = CsvGazeReader::new(reader).with_binocular(options.eyes);
            if let Some(screen) = options.screen {
                reader = reader.with_screen(screen);
            }
            SampleReader::Csv(reader)
        }
        RecordingFormat::Asc => {
            let mut reader = AscReader::new(reader).with_binocular(options.eyes);
            if let Some(screen) = options.screen {
                reader = reader.with_screen(screen);
            }
            SampleReader::Asc(reader)
        }
    }
}

/// What a look ahead into a recording found, before anything is sent: enough to refuse a file
/// that would send nothing with one clear error, and to say what pacing will do to it.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct RecordingScan {
    /// Samples read (at most the limit the scan was given).
    pub samples: u64,
    /// Whether the scan read the whole file (then `samples` is all of them).
    pub complete: bool,
    /// Lines that did not parse.
    pub malformed: u64,
    /// The first of them, as the reader reported it.
    pub first_error: Option<String>,
    /// The sample rate: one over the median step between consecutive distinct timestamps.
    pub rate_hz: Option<f64>,
    /// Whether the recording holds both eyes.
    pub binocular: bool,
    /// The eye the samples are tagged with (of the first sample).
    pub eye: Option<Eye>,
}

impl RecordingScan {
    /// Why nothing would be sent from `path`, if nothing would: one sentence for the one error.
    #[must_use]
    pub fn nothing_to_send(&self, path: &Path) -> Option<String> {
        if self.samples > 0 {
            return None;
        }
        Some(match &self.first_error {
            None => format!(
                "{} has no gaze sample to send: it has no data line (it is empty, or holds only \
                 a header and comments)",
                path.display()
            ),
            Some(first) => format!(
                "{} has no gaze sample to send: all {} of its data lines were skipped; the \
                 first: {first}",
                path.display(),
                self.malformed
            ),
        })
    }
}

/// Reads up to `max_samples` samples of the recording at `path` (all of it when it holds no
/// more), without sending anything.
///
/// # Errors
/// The file cannot be opened or read.
pub fn scan_recording(
    path: &Path,
    options: ReadOptions,
    max_samples: u64,
) -> io::Result<RecordingScan> {
    let file = File::open(path)?;
    let (head, reader) = peek(file)?;
    let format = options
        .format
        .unwrap_or_else(|| detect_format(Some(path), &head));
    let mut reader = sample_reader(format, BufReader::new(reader), &options);
    let mut scan = RecordingScan {
        complete: true,
        ..RecordingScan::default()
    };
    let mut steps = Vec::new();
    let mut previous: Option<f64> = None;
    for item in reader.by_ref() {
        match item {
            Ok(sample) => {
                scan.samples += 1;
                scan.eye.get_or_insert(sample.eye);
                if let Some(p) = previous
                    && sample.t_s > p
                {
                    steps.push(sample.t_s - p);
                }
                previous = Some(sample.t_s);
                if scan.samples >= max_samples {
                    scan.complete = false;
                    break;
                }
            }
            Err(ParseError::Io { line, source }) => {
                return Err(io::Error::new(
                    source.kind(),
                    format!("line {line}: {source}"),
                ));
            }
            Err(err) => {
                scan.malformed += 1;
                scan.first_error.get_or_insert_with(|| err.to_string());
            }
        }
    }
    scan.binocular = reader.binocular();
    steps.sort_by(f64::total_cmp);
    scan.rate_hz = steps
        .get(steps.len() / 2)
        .map(|step| 1.0 / step)
        .filter(|r| r.is_finite());
    Ok(scan)
}

/// CSV lines from standard input, each forwarded as soon as its line ends (the CSV reader pulls
/// one line per sample, so nothing waits for more input than the current line).
#[must_use]
pub fn stdin_csv(screen: Option<ScreenPx>, eyes: Binocular) -> mpsc::Receiver<SourceItem> {
    // The lock is taken on the reader thread: `StdinLock` cannot cross threads.
    spawn_with("stdin", move || {
        let mut reader = CsvGazeReader::new(io::stdin().lock()).with_binocular(eyes);
        if let Some(screen) = screen {
            reader = reader.with_screen(screen);
        }
        reader.map(|r| r.map_err(SourceError::from))
    })
}

/// Where and how to reach a Gazepoint tracker (Open Gaze API).
#[derive(Debug, Clone)]
pub struct GazepointOptions {
    /// Host name or address.
    pub host: String,
    /// TCP port.
    pub port: u16,
    /// Time allowed for one connection attempt.
    pub connect_timeout: Duration,
    /// Attempts after the first failure before giving up (per outage, reset by a connection
    /// that worked).
    pub max_retries: u32,
    /// Wait after the first failure; doubled after each further failure.
    pub initial_backoff: Duration,
    /// Longest wait between attempts.
    pub max_backoff: Duration,
}

impl Default for GazepointOptions {
    fn default() -> Self {
        Self {
            host: "127.0.0.1".into(),
            port: opengaze::DEFAULT_PORT,
            connect_timeout: Duration::from_secs(3),
            max_retries: 5,
            initial_backoff: Duration::from_millis(200),
            max_backoff: Duration::from_secs(5),
        }
    }
}

/// Longest line accepted from the tracker; a peer that never sends a line end must not grow the
/// buffer without bound. A longer line is reported malformed, in pieces of this size.
const MAX_LINE_BYTES: u64 = 64 * 1024;

/// A live Gazepoint tracker as a source: connects, sends the `SET` handshake, then forwards
/// every `REC` line (valid and invalid samples alike; malformed lines as
/// [`SourceError::Parse`]). A connection that fails or drops is retried with exponential
/// backoff; the tracker closing the connection cleanly (EOF) ends the source.
///
/// # Panics
/// When called outside a tokio runtime.
#[must_use]
pub fn gazepoint(options: GazepointOptions) -> mpsc::Receiver<SourceItem> {
    let (tx, rx) = mpsc::channel(CHANNEL_CAPACITY);
    tokio::spawn(run_gazepoint(options, tx));
    rx
}

/// How one connection ended.
enum ConnectionEnd {
    /// The tracker closed the connection.
    Eof,
    /// Nobody listens to the source any more.
    ReceiverGone,
}

async fn run_gazepoint(options: GazepointOptions, tx: mpsc::Sender<SourceItem>) {
    let addr = format!("{}:{}", options.host, options.port);
    // Line numbers run on across reconnections, so log lines stay unambiguous.
    let mut line = 0usize;
    let mut failures = 0u32;
    let mut backoff = options.initial_backoff;
    loop {
        let outcome = match connect_gazepoint(&addr, options.connect_timeout).await {
            Ok(stream) => {
                info!(%addr, "connected to the Gazepoint tracker");
                failures = 0;
                backoff = options.initial_backoff;
                read_gazepoint(stream, &mut line, &tx).await
            }
            Err(err) => Err(err),
        };
        let err = match outcome {
            Ok(ConnectionEnd::Eof) => {
                info!(%addr, "the tracker closed the connection");
                return;
            }
            Ok(ConnectionEnd::ReceiverGone) => return,
            Err(err) => err,
        };
        if failures >= options.max_retries {
            let what = format!("Gazepoint tracker at {addr} (gave up after {failures} retries)");
            let _ = tx.send(Err(SourceError::Io { what, source: err })).await;
            return;
        }
        failures += 1;
        warn!(%addr, error = %err, retry_in_ms = backoff.as_millis(), "Gazepoint connection failed; retrying");
        tokio::select! {
            () = tokio::time::sleep(backoff) => {}
            () = tx.closed() => return,
        }
        backoff = (backoff * 2).min(options.max_backoff);
    }
}

/// Connects and sends the handshake.
async fn connect_gazepoint(addr: &str, timeout: Duration) -> io::Result<TcpStream> {
    let mut stream = tokio::time::timeout(timeout, TcpStream::connect(addr))
        .await
        .map_err(|_| io::Error::new(io::ErrorKind::TimedOut, "connect timed out"))??;
    stream.set_nodelay(true)?;
    for command in opengaze::handshake_commands() {
        stream.write_all(command.as_bytes()).await?;
    }
    stream.flush().await?;
    Ok(stream)
}

/// Reads lines until EOF, an I/O error or the receiver going away.
async fn read_gazepoint(
    stream: TcpStream,
    line: &mut usize,
    tx: &mpsc::Sender<SourceItem>,
) -> io::Result<ConnectionEnd> {
    let mut reader = AsyncBufReader::new(stream);
    let mut buf = Vec::new();
    loop {
        buf.clear();
        let n = AsyncReadExt::take(&mut reader, MAX_LINE_BYTES)
            .read_until(b'\n', &mut buf)
            .await?;
        if n == 0 {
            return Ok(ConnectionEnd::Eof);
        }
        *line += 1;
        let item = match std::str::from_utf8(&buf) {
            Ok(text) if !text.ends_with('\n') && n as u64 == MAX_LINE_BYTES => {
                Some(Err(SourceError::Parse(ParseError::Malformed {
                    line: *line,
                    field: "line",
                    reason: format!("longer than {MAX_LINE_BYTES} bytes"),
                })))
            }
            Ok(text) => match opengaze::parse_line(*line, text) {
                Ok(Some(OpenGazeMessage::Record(record))) => Some(Ok(record.to_sample())),
                Ok(Some(OpenGazeMessage::Ack { id, state })) => {
                    debug!(line = *line, %id, ?state, "tracker acknowledged");
                    None
                }
                Ok(Some(OpenGazeMessage::Other { tag, id })) => {
                    debug!(line = *line, %tag, ?id, "tracker sent another element");
                    None
                }
                Ok(None) => None,
                Err(err) => Some(Err(SourceError::Parse(err))),
            },
            Err(_) => Some(Err(SourceError::Parse(ParseError::Malformed {
                line: *line,
                field: "line",
                reason: "is not valid UTF-8".into(),
            }))),
        };
        if let Some(item) = item
            && tx.send(item).await.is_err()
        {
            return Ok(ConnectionEnd::ReceiverGone);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn extension_wins_then_content_decides() {
        let asc_head = b"** CONVERTED FROM x.edf\nMSG 1 DISPLAY_COORDS 0 0 1919 1079\n";
        let csv_head = b"# screen 1920x1080 px\nt_s,xpos,ypos,ps\n0.0,1,2,3\n";
        assert_eq!(
            detect_format(Some(Path::new("a.ASC")), csv_head),
            RecordingFormat::Asc
        );
        assert_eq!(
            detect_format(Some(Path::new("a.csv")), asc_head),
            RecordingFormat::Csv
        );
        assert_eq!(
            detect_format(Some(Path::new("a.txt")), asc_head),
            RecordingFormat::Asc
        );
        assert_eq!(detect_format(None, csv_head), RecordingFormat::Csv);
        assert_eq!(
            sniff_format(b"\n\n1000\t960.0\t540.0\t1103.0\t...\n"),
            RecordingFormat::Asc
        );
        assert_eq!(sniff_format(b"SAMPLES GAZE LEFT\n"), RecordingFormat::Asc);
        assert_eq!(sniff_format(b""), RecordingFormat::Csv);
        assert_eq!(sniff_format(b"garbage\n"), RecordingFormat::Csv);
    }

    #[test]
    fn the_real_recordings_are_detected_by_content() {
        // The recording ships in the repository's `data/gaze`.
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../data/gaze");
        for (name, expected) in [
            ("eyelink-1000hz-left.asc", RecordingFormat::Asc),
            ("eyelink-1000hz-left.samples.csv", RecordingFormat::Csv),
        ] {
            let path = dir.join(name);
            let file = File::open(&path).unwrap_or_else(|e| panic!("open {}: {e}", path.display()));
            let (head, _) = peek(file).expect("readable");
            assert_eq!(sniff_format(&head), expected, "{name}");
        }
    }

    #[test]
    fn peek_gives_back_every_byte() {
        let data: Vec<u8> = (0..SNIFF_BYTES * 2 + 7).map(|i| (i % 251) as u8).collect();
        let (head, mut rest) = peek(data.as_slice()).expect("reads");
        assert_eq!(head.len(), SNIFF_BYTES);
        let mut all = Vec::new();
        rest.read_to_end(&mut all).expect("reads");
        assert_eq!(all, data);
    }

    #[test]
    fn a_scan_finds_the_rate_the_eyes_and_files_that_send_nothing() {
        let dir = std::env::temp_dir();
        let write = |name: &str, text: &str| {
            let path = dir.join(format!("foveal-scan-{}-{name}", std::process::id()));
            std::fs::write(&path, text).expect("write");
            path
        };
        let options = ReadOptions::default();
        let binocular = write(
            "bino.csv",
            "t_s,x_left,y_left,x_right,y_right\n0,0.2,0.5,0.8,0.5\n0.002,0.2,0.5,0.8,0.5\n\
             0.004,0.2,0.5,0.8,0.5\n",
        );
        let scan = scan_recording(&binocular, options, 1000).expect("scans");
        assert_eq!(
            (scan.samples, scan.complete, scan.binocular),
            (3, true, true)
        );
        assert!((scan.rate_hz.expect("a rate") - 500.0).abs() < 1e-6);
        let left = ReadOptions {
            eyes: Binocular::Left,
            ..options
        };
        assert_eq!(
            scan_recording(&binocular, left, 2).expect("scans"),
            RecordingScan {
                samples: 2,
                complete: false,
                rate_hz: Some(1.0 / 0.002),
                binocular: true,
                eye: Some(Eye::Left),
                ..RecordingScan::default()
            }
        );
        for (name, text, why) in [
            ("empty.csv", "", "no data line"),
            ("header.csv", "# a comment\nt_s,x,y\n", "no data line"),
            (
                "noscreen.csv",
                "t_s,xpos,ypos\n0,1,2\n0.001,1,2\n",
                "all 2 of its data lines were skipped; the first: line 2: field `xpos`",
            ),
        ] {
            let path = write(name, text);
            let scan = scan_recording(&path, options, 1000).expect("scans");
            let message = scan.nothing_to_send(&path).expect("nothing to send");
            assert!(message.contains(why), "{message}");
            let _ = std::fs::remove_file(path);
        }
        let _ = std::fs::remove_file(binocular);
    }

    #[test]
    fn parse_errors_go_on_but_read_errors_end() {
        let parse = ParseError::MissingField {
            line: 3,
            field: "x",
        };
        assert!(matches!(SourceError::from(parse), SourceError::Parse(_)));
        let io = ParseError::Io {
            line: 4,
            source: io::Error::other("disk"),
        };
        assert!(matches!(SourceError::from(io), SourceError::Io { .. }));
    }
}
