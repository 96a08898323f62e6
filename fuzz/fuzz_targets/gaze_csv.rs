//! CSV gaze lines (files and stdin of `foveal bridge csv`): never panic, and every sample the reader
//! accepts as valid has finite coordinates and time.
#![no_main]
use foveal_gaze::csv::CsvGazeReader;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    for s in CsvGazeReader::new(data).flatten() {
        if s.is_valid() {
            assert!(s.t_s.is_finite() && s.x.is_finite() && s.y.is_finite(), "{s:?}");
        }
    }
});
