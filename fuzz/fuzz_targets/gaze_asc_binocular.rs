//! Binocular EyeLink ASC files (`SAMPLES GAZE LEFT RIGHT`), every way of using the eyes: never
//! panic, valid samples are finite.
#![no_main]
use foveal_gaze::Binocular;
use foveal_gaze::asc::AscReader;
use libfuzzer_sys::fuzz_target;

const HEAD: &str = "MSG\t1000 DISPLAY_COORDS 0 0 1919 1079\nSAMPLES\tGAZE\tLEFT\tRIGHT\tRATE\t1000.00\n";

fuzz_target!(|data: &[u8]| {
    let mut input = HEAD.as_bytes().to_vec();
    input.extend_from_slice(data);
    for eyes in [Binocular::Mean, Binocular::Left, Binocular::Right, Binocular::Both] {
        for s in AscReader::new(input.as_slice()).with_binocular(eyes).flatten() {
            if s.is_valid() {
                assert!(s.t_s.is_finite() && s.x.is_finite() && s.y.is_finite(), "{s:?}");
            }
        }
    }
});
