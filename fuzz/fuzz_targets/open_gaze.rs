//! Gazepoint Open Gaze records arriving over TCP (`foveal bridge gazepoint`): never panic, and valid
//! samples are finite.
#![no_main]
use foveal_gaze::opengaze::OpenGazeParser;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    let mut parser = OpenGazeParser::new();
    for line in text.split("\r\n") {
        if let Ok(Some(s)) = parser.push_line(line) {
            if s.is_valid() {
                assert!(s.t_s.is_finite() && s.x.is_finite() && s.y.is_finite(), "{s:?}");
            }
        }
    }
});
