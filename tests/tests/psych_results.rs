//! The psychophysics results endpoint over a real socket: a session is started, a trial is
//! stored and read back by `foveal psych fit`'s reader, malformed trials are refused with the
//! field named and change nothing stored, and only the writer's role (gaze, or admin) may write.

use std::path::{Path, PathBuf};

use foveal_server::psych::PsychConfig;
use foveal_server::{Role, Tokens};
use foveal_tests::{TestServer, small_config, within};
use tokio::io::{AsyncReadExt, AsyncWriteExt};

/// A fresh directory in the system's temporary directory, removed on drop.
struct TempDir(PathBuf);

impl TempDir {
    fn new(name: &str) -> Self {
        let nanos = std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map_or(0, |d| d.as_nanos());
        Self(std::env::temp_dir().join(format!("foveal-{name}-{}-{nanos}", std::process::id())))
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// One HTTP/1.1 exchange on a fresh connection: the status and the body.
async fn http(
    server: &TestServer,
    method: &str,
    path: &str,
    token: Option<&str>,
    content_type: &str,
    body: &[u8],
) -> (u16, String) {
    let mut s = tokio::net::TcpStream::connect(server.addr)
        .await
        .expect("connect");
    let auth = token.map_or_else(String::new, |t| format!("Authorization: Bearer {t}\r\n"));
    let head = format!(
        "{method} {path} HTTP/1.1\r\nHost: localhost\r\nConnection: close\r\n{auth}Content-Type: {content_type}\r\nContent-Length: {}\r\n\r\n",
        body.len()
    );
    s.write_all(head.as_bytes()).await.expect("send head");
    // A body the server refuses by its declared length may be cut short: that is the point.
    let _ = s.write_all(body).await;
    let mut out = Vec::new();
    let _ = within("the HTTP response", s.read_to_end(&mut out)).await;
    let text = String::from_utf8_lossy(&out).into_owned();
    let status = text
        .get(9..12)
        .and_then(|c| c.parse().ok())
        .unwrap_or_else(|| panic!("not an HTTP response: {text}"));
    let body = text
        .split_once("\r\n\r\n")
        .map(|(_, b)| b.to_owned())
        .unwrap_or_default();
    (status, body)
}

async fn post(server: &TestServer, path: &str, token: Option<&str>, body: &str) -> (u16, String) {
    http(
        server,
        "POST",
        path,
        token,
        "application/json",
        body.as_bytes(),
    )
    .await
}

fn session_json(participant: &str) -> String {
    format!(
        r#"{{"participant":"{participant}","session":"1","design":"experiment1","display":{{"px_per_cm":35.4,"px_per_cm_source":"calibration","viewing_distance_cm":70,"window_width_px":1680,"window_height_px":1050,"device_pixel_ratio":1,"refresh_ms":16.67}}}}"#
    )
}

/// Trial `n` of experiment 1: 5 degrees up, the small gap, answered "apart"; `edit` changes
/// one field.
fn trial_json(n: u32, edit: &[(&str, serde_json::Value)]) -> String {
    let mut v = serde_json::json!({
        "trial": n, "block": 1, "cell": 16,
        "eccentricity_deg": 5, "direction_deg": 90, "gap_label": "small", "gap_deg": 0.05,
        "response": "apart", "response_source": "key", "rt_ms": 532.1,
        "valid": true, "invalid_reason": "", "repeat_of": null,
        "duration_ms": 150.1, "intended_ms": 150, "frames": 9, "refresh_ms": 16.67,
        "onset_ms": 2100.5, "gap_px": 2.17, "x_px": 0, "y_px": 216.9,
        "frame_ms": [0, 16.7, 33.3, 50, 66.7, 83.3, 100, 116.7, 133.3, 150.1],
    });
    for (k, val) in edit {
        if val.is_null() {
            v.as_object_mut().expect("object").remove(*k);
        } else {
            v[*k] = val.clone();
        }
    }
    v.to_string()
}

/// Fields of a trial to change (a null removes the field).
type Edit<'a> = Vec<(&'a str, serde_json::Value)>;

fn field_of(body: &str) -> String {
    let v: serde_json::Value = serde_json::from_str(body).unwrap_or_else(|e| panic!("{e}: {body}"));
    v["field"].as_str().unwrap_or_default().to_owned()
}

fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn trials_are_appended_and_malformed_ones_refused_by_field() {
    let dir = TempDir::new("psych-results");
    let mut config = small_config(50, 60.0);
    config.psych = PsychConfig {
        results_dir: dir.0.clone(),
        designs_dir: None,
    };
    let server = TestServer::start(config).await;
    let _ = server.client().await;

    let (status, body) = http(
        &server,
        "GET",
        "/psych/api/design?name=experiment1",
        None,
        "text/plain",
        b"",
    )
    .await;
    assert_eq!(status, 200, "{body}");
    assert!(body.contains("\"trials\":240"), "{body}");
    let (status, body) = http(
        &server,
        "GET",
        "/psych/api/design?name=nope",
        None,
        "text/plain",
        b"",
    )
    .await;
    assert_eq!(
        (status, field_of(&body).as_str()),
        (404, "design"),
        "{body}"
    );

    let (status, body) = post(&server, "/psych/api/sessions", None, &session_json("P07")).await;
    assert_eq!(status, 201, "{body}");
    let started: serde_json::Value = serde_json::from_str(&body).expect("JSON");
    let id = started["session"]
        .as_str()
        .expect("a session id")
        .to_owned();
    assert_eq!(started["results"], "P07_1.csv");
    let trials = format!("/psych/api/sessions/{id}/trials");

    let (status, body) = post(&server, &trials, None, &trial_json(1, &[])).await;
    assert_eq!(status, 201, "{body}");
    let csv = dir.0.join("P07_1.csv");
    let stored = read(&csv);

    // Each malformed trial is refused naming its field, and the file does not change.
    let cases: Vec<(Edit, &str, u16)> = vec![
        (vec![("gap_deg", 0.06.into())], "gap_deg", 400),
        (
            vec![("eccentricity_deg", "far".into())],
            "eccentricity_deg",
            400,
        ),
        (
            vec![("eccentricity_deg", 7.into())],
            "eccentricity_deg",
            400,
        ),
        (vec![("response", "yes".into())], "response", 400),
        (vec![("cell", 3.into())], "cell", 400),
        (vec![("rt_ms", serde_json::Value::Null)], "rt_ms", 400),
        (vec![("colour", "red".into())], "colour", 400),
        (vec![("valid", false.into())], "invalid_reason", 400),
        (
            vec![("frame_ms", serde_json::json!(vec![0.0; 1001]))],
            "frame_ms",
            400,
        ),
        (vec![("trial", 1.into())], "trial", 409),
    ];
    for (edit, field, code) in cases {
        let n = if field == "trial" { 1 } else { 2 };
        let (status, body) = post(&server, &trials, None, &trial_json(n, &edit)).await;
        assert_eq!(
            (status, field_of(&body).as_str()),
            (code, field),
            "{edit:?}: {body}"
        );
        assert!(body.contains(field), "the message names `{field}`: {body}");
    }
    let (status, body) = post(&server, &trials, None, "{\"trial\": 2,").await;
    assert_eq!((status, field_of(&body).as_str()), (400, "body"), "{body}");
    let (status, body) = http(&server, "POST", &trials, None, "text/csv", b"1,2,3").await;
    assert_eq!(status, 415, "{body}");
    let huge = format!("{{\"pad\": \"{}\"}}", "x".repeat(100_000));
    let (status, body) = post(&server, &trials, None, &huge).await;
    assert_eq!((status, field_of(&body).as_str()), (413, "body"), "{body}");
    let (status, body) = post(
        &server,
        "/psych/api/sessions/0123456789abcdef/trials",
        None,
        &trial_json(2, &[]),
    )
    .await;
    assert_eq!(
        (status, field_of(&body).as_str()),
        (404, "session"),
        "{body}"
    );
    // The same participant and session again: refused, the stored file untouched.
    let (status, body) = post(&server, "/psych/api/sessions", None, &session_json("P07")).await;
    assert_eq!(
        (status, field_of(&body).as_str()),
        (409, "session"),
        "{body}"
    );
    let (status, body) = post(
        &server,
        "/psych/api/sessions",
        None,
        &session_json("Jane Doe"),
    )
    .await;
    assert_eq!(
        (status, field_of(&body).as_str()),
        (400, "participant"),
        "{body}"
    );
    assert_eq!(read(&csv), stored, "refused requests changed the results");

    let (status, body) = post(
        &server,
        &trials,
        None,
        &trial_json(
            2,
            &[
                ("valid", false.into()),
                ("invalid_reason", "late_frame".into()),
            ],
        ),
    )
    .await;
    assert_eq!(status, 201, "{body}");
    let (status, body) = post(
        &server,
        &trials,
        None,
        &trial_json(
            3,
            &[("repeat_of", 2.into()), ("response", "touching".into())],
        ),
    )
    .await;
    assert_eq!(status, 201, "{body}");
    let (status, body) = post(
        &server,
        &format!("/psych/api/sessions/{id}/finish"),
        None,
        "{\"completed\": true}",
    )
    .await;
    assert_eq!((status, body.trim()), (200, "{\"trials_stored\":3}"));

    let text = read(&csv);
    let mut lines = text.lines();
    assert_eq!(
        lines.next(),
        Some(foveal_server::psych::trial::COLUMNS.join(",").as_str())
    );
    let rows: Vec<&str> = lines.collect();
    assert_eq!(rows.len(), 3, "{text}");
    assert!(rows[0].starts_with("P07,1,experiment1,1,1,16,5,90,small,0.05,apart,1,key,532.1,1,,,150.100,150,9,16.670,2100.5,2.170,0.00,216.90,0.000;16.700;"), "{}", rows[0]);
    assert!(rows[1].contains(",0,late_frame,,"), "{}", rows[1]);
    assert!(rows[2].contains(",1,,2,"), "{}", rows[2]);
    // `foveal psych fit` reads it: the invalid trial dropped, the others as posted.
    let read_back = foveal_psych::trial::parse_csv("P07_1.csv", &text).expect("psych fit reads it");
    assert_eq!(read_back.len(), 2);
    assert_eq!(
        (
            read_back[0].participant.as_str(),
            read_back[0].eccentricity_deg,
            read_back[0].gap_deg,
            read_back[0].apart
        ),
        ("P07", 5.0, 0.05, true)
    );
    assert!(!read_back[1].apart);

    let header: serde_json::Value =
        serde_json::from_str(&read(&dir.0.join("P07_1.json"))).expect("JSON header");
    assert_eq!(header["design"]["name"], "experiment1");
    assert_eq!(header["display"]["configured"]["diagonal_in"], 22.0);
    assert_eq!(
        header["display"]["browser"]["px_per_cm_source"],
        "calibration"
    );
    assert_eq!(header["software"]["version"], env!("CARGO_PKG_VERSION"));
    assert_eq!(
        (
            header["completed"].as_bool(),
            header["trials_stored"].as_u64()
        ),
        (Some(true), Some(3))
    );
    let (status, body) = post(&server, &trials, None, &trial_json(4, &[])).await;
    assert_eq!(
        (status, field_of(&body).as_str()),
        (404, "session"),
        "a finished session takes no more trials: {body}"
    );
    server.stop().await.expect("clean stop");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn only_the_gaze_role_or_admin_may_write_results() {
    const VIEWER: &str = "viewer-secret-0123456789";
    const GAZE: &str = "gaze-secret-0123456789";
    let dir = TempDir::new("psych-roles");
    let mut config = small_config(50, 60.0);
    config.psych.results_dir = dir.0.clone();
    let mut tokens = Tokens::none();
    tokens.add(Role::Viewer, VIEWER, "test").expect("token");
    tokens.add(Role::Gaze, GAZE, "test").expect("token");
    config.security.tokens = tokens;
    let server = TestServer::start(config).await;
    let (status, body) = post(&server, "/psych/api/sessions", None, &session_json("P01")).await;
    assert_eq!(status, 401, "{body}");
    let (status, body) = post(
        &server,
        "/psych/api/sessions",
        Some(VIEWER),
        &session_json("P01"),
    )
    .await;
    assert_eq!(status, 403, "{body}");
    assert!(body.contains("`gaze` role"), "{body}");
    let (status, body) = post(
        &server,
        "/psych/api/sessions",
        Some(GAZE),
        &session_json("P01"),
    )
    .await;
    assert_eq!(status, 201, "{body}");
    assert!(!dir.0.join("P02_1.csv").exists());
    assert!(dir.0.join("P01_1.csv").exists());
    server.stop().await.expect("clean stop");
}
