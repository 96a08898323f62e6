//! Lab Streaming Layer messages arriving from the network (`foveal bridge lsl`): the resolve
//! reply with its shortinfo XML, the stream feed's response head, a sample's channel bytes and a
//! time-probe reply. Never panic; a decoded sample is valid only with finite coordinates.
#![no_main]
use foveal_gaze::lsl::{
    ChannelFormat, ChannelMap, FeedResponse, StreamInfo, TimeProbe, decode_values,
    parse_feed_response, parse_resolve_reply,
};
use libfuzzer_sys::fuzz_target;

const FORMATS: [ChannelFormat; 6] = [
    ChannelFormat::Float32,
    ChannelFormat::Double64,
    ChannelFormat::Int32,
    ChannelFormat::Int16,
    ChannelFormat::Int8,
    ChannelFormat::Int64,
];

fuzz_target!(|data: &[u8]| {
    let Some((&selector, rest)) = data.split_first() else {
        return;
    };
    let text = String::from_utf8_lossy(rest);
    match selector % 4 {
        0 => {
            let _ = parse_resolve_reply(&text, "q1");
            if let Ok(info) = StreamInfo::parse(&text) {
                let _ = ChannelMap::default().check(info.channel_count);
            }
        }
        1 => {
            let _ = parse_feed_response(&text, "uid");
        }
        2 => {
            let format = FORMATS[usize::from(selector / 4) % FORMATS.len()];
            let response = FeedResponse {
                big_endian: selector & 0x80 != 0,
                suppress_subnormals: selector & 0x40 != 0,
            };
            let values = decode_values(format, rest, response);
            let s = ChannelMap::default().sample(1.0, &values);
            if s.is_valid() {
                assert!(s.x.is_finite() && s.y.is_finite(), "{s:?}");
            }
        }
        _ => {
            if let Some(p) = TimeProbe::from_reply(&text, 7, 2.0) {
                let _ = (p.rtt(), p.correction());
            }
        }
    }
});
