//! EyeLink ASC files (`foveal bridge asc`, `foveal gaze replay`): never panic, and valid samples are
//! finite.
#![no_main]
use foveal_gaze::asc::AscReader;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    for s in AscReader::new(data).flatten() {
        if s.is_valid() {
            assert!(s.t_s.is_finite() && s.x.is_finite() && s.y.is_finite(), "{s:?}");
        }
    }
});
