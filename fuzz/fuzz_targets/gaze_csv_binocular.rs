//! Binocular CSV (an EyeLink binocular export and the normalised `_left`/`_right` layout), every
//! way of using the eyes: never panic, valid samples are finite, and `Both` gives two samples per
//! line, left then right, at one time.
#![no_main]
use foveal_gaze::Binocular;
use foveal_gaze::csv::CsvGazeReader;
use libfuzzer_sys::fuzz_target;

const HEADERS: [&str; 2] = [
    "# screen 1920x1080 px\nt_s,xpos_left,xpos_right,ypos_left,ypos_right,ps_left,ps_right\n",
    "t_s,x_left,y_left,validity_left,x_right,y_right,validity_right,fixation\n",
];

fuzz_target!(|data: &[u8]| {
    let Some((&selector, body)) = data.split_first() else { return };
    let mut input = HEADERS[usize::from(selector & 1)].as_bytes().to_vec();
    input.extend_from_slice(body);
    for eyes in [Binocular::Mean, Binocular::Left, Binocular::Right] {
        for s in CsvGazeReader::new(input.as_slice()).with_binocular(eyes).flatten() {
            if s.is_valid() {
                assert!(s.t_s.is_finite() && s.x.is_finite() && s.y.is_finite(), "{s:?}");
                assert!((0.0..=1.0).contains(&s.validity), "{s:?}");
            }
        }
    }
    let both: Vec<_> = CsvGazeReader::new(input.as_slice())
        .with_binocular(Binocular::Both)
        .flatten()
        .collect();
    assert_eq!(both.len() % 2, 0);
    for pair in both.chunks(2) {
        assert_eq!(pair[0].t_s, pair[1].t_s);
        assert_eq!((pair[0].eye, pair[1].eye), (foveal_gaze::Eye::Left, foveal_gaze::Eye::Right));
    }
});
