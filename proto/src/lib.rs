//! # foveal-proto
//!
//! The gRPC protocol of foveal (`proto/foveal/v1/foveal.proto`, package `foveal.v1`).
//!
//! # Layout
//! - [`pb`]: generated message types, the `foveal_client::FovealClient` and the
//!   `foveal_server::{Foveal, FovealServer}` pair.
//! - [`quantise`]: packing of `QuantisedPoses` (16-bit positions, smallest-three quaternions) and
//!   of `Collisions`, with the decoders a Rust client uses.
//! - [`FILE_DESCRIPTOR_SET`]: the encoded `FileDescriptorSet` of the protocol, for gRPC
//!   server reflection.
//!
//! Conventions (documented on every field of the `.proto`): screen coordinates normalised to
//! 0..1 with the origin at the top-left, x right and y down; times in seconds as `f64`;
//! lengths in scene units.

/// Generated code of package `foveal.v1`.
#[allow(
    missing_docs,
    clippy::all,
    clippy::pedantic,
    missing_debug_implementations
)]
pub mod pb {
    tonic::include_proto!("foveal.v1");
}

pub mod quantise;

impl pb::Poses {
    /// Pack positions (relative to `origin`) and orientations (x, y, z, w) as little-endian f32.
    pub fn pack(
        origin: pb::Vec3,
        positions: impl ExactSizeIterator<Item = [f32; 3]>,
        orientations: impl Iterator<Item = [f32; 4]>,
    ) -> Self {
        let bodies = positions.len();
        let mut pos = Vec::with_capacity(12 * bodies);
        for p in positions {
            p.iter()
                .for_each(|v| pos.extend_from_slice(&v.to_le_bytes()));
        }
        let mut rot = Vec::with_capacity(16 * bodies);
        for q in orientations {
            q.iter()
                .for_each(|v| rot.extend_from_slice(&v.to_le_bytes()));
        }
        Self {
            positions: pos.into(),
            orientations: rot.into(),
            origin: Some(origin),
            bodies: u32::try_from(bodies).unwrap_or(u32::MAX),
        }
    }

    /// Positions relative to `origin`, one (x, y, z) per body (a trailing partial triple is ignored).
    pub fn positions_f32(&self) -> impl Iterator<Item = [f32; 3]> + '_ {
        self.positions
            .chunks_exact(12)
            .map(|c| [f32_at(c, 0), f32_at(c, 4), f32_at(c, 8)])
    }

    /// Orientations, one unit quaternion (x, y, z, w) per body.
    pub fn orientations_f32(&self) -> impl Iterator<Item = [f32; 4]> + '_ {
        self.orientations
            .chunks_exact(16)
            .map(|c| [f32_at(c, 0), f32_at(c, 4), f32_at(c, 8), f32_at(c, 12)])
    }
}

fn f32_at(c: &[u8], i: usize) -> f32 {
    f32::from_le_bytes([c[i], c[i + 1], c[i + 2], c[i + 3]])
}

/// Encoded `google.protobuf.FileDescriptorSet` of `foveal/v1/foveal.proto`, for reflection.
pub const FILE_DESCRIPTOR_SET: &[u8] =
    include_bytes!(concat!(env!("OUT_DIR"), "/foveal_descriptor.bin"));

#[cfg(test)]
mod tests {
    use prost::Message;
    use prost_types::FileDescriptorSet;

    use super::FILE_DESCRIPTOR_SET;

    fn service() -> prost_types::ServiceDescriptorProto {
        let fds = FileDescriptorSet::decode(FILE_DESCRIPTOR_SET).expect("descriptor set decodes");
        let file = fds
            .file
            .iter()
            .find(|f| f.package() == "foveal.v1")
            .expect("file of package foveal.v1");
        file.service
            .iter()
            .find(|s| s.name() == "Foveal")
            .cloned()
            .expect("service Foveal")
    }

    #[test]
    fn descriptor_set_has_the_eleven_methods_with_their_streaming_kinds() {
        let service = service();
        // (name, client streaming, server streaming)
        let expected = [
            ("StreamGaze", true, false),
            ("PushGaze", false, false),
            ("WatchFrames", false, true),
            ("GetScene", false, false),
            ("Configure", false, false),
            ("GetStatus", false, false),
            ("Pause", false, false),
            ("Resume", false, false),
            ("Step", false, false),
            ("Restart", false, false),
            ("InspectBody", false, false),
        ];
        assert_eq!(service.method.len(), expected.len());
        for (name, client_streaming, server_streaming) in expected {
            let method = service
                .method
                .iter()
                .find(|m| m.name() == name)
                .unwrap_or_else(|| panic!("method {name}"));
            assert_eq!(
                method.client_streaming(),
                client_streaming,
                "{name} client streaming"
            );
            assert_eq!(
                method.server_streaming(),
                server_streaming,
                "{name} server streaming"
            );
        }
    }

    #[test]
    fn descriptor_set_keeps_comments_and_byte_packed_poses() {
        let fds = FileDescriptorSet::decode(FILE_DESCRIPTOR_SET).expect("descriptor set decodes");
        let file = fds
            .file
            .iter()
            .find(|f| f.package() == "foveal.v1")
            .expect("file");
        assert!(
            file.source_code_info
                .as_ref()
                .is_some_and(|s| !s.location.is_empty()),
            "source info (comments) is kept for reflection"
        );
        let poses = file
            .message_type
            .iter()
            .find(|m| m.name() == "Poses")
            .expect("Poses");
        for field in &poses.field {
            if field.name() == "positions" || field.name() == "orientations" {
                assert_eq!(
                    field.r#type(),
                    prost_types::field_descriptor_proto::Type::Bytes,
                    "{}",
                    field.name()
                );
            }
        }
    }

    #[test]
    fn generated_types_round_trip() {
        use super::pb;
        let frame = pb::Frame {
            index: 7,
            sim_time_s: 0.125,
            fixation: Some(pb::Fixation {
                x: 0.25,
                y: 0.75,
                age_s: 0.01,
                source: pb::FixationSource::Gaze as i32,
                ..Default::default()
            }),
            poses: Some(pb::Poses::pack(
                pb::Vec3 {
                    x: 10.0,
                    y: 0.0,
                    z: -1.0,
                },
                [[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]].into_iter(),
                [[0.0, 0.0, 0.0, 1.0], [0.5, 0.5, 0.5, 0.5]].into_iter(),
            )),
            ..Default::default()
        };
        let bytes = frame.encode_to_vec();
        let back = pb::Frame::decode(bytes.as_slice()).expect("decodes");
        assert_eq!(back, frame);
        let poses = back.poses.expect("poses");
        assert_eq!(poses.bodies, 2);
        assert_eq!(
            poses.positions_f32().collect::<Vec<_>>(),
            vec![[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]]
        );
        assert_eq!(poses.orientations_f32().nth(1), Some([0.5; 4]));

        let sample = pb::GazeSample {
            fixation: None,
            eye: pb::Eye::Left as i32,
            ..Default::default()
        };
        let back = pb::GazeSample::decode(sample.encode_to_vec().as_slice()).expect("decodes");
        assert_eq!(back.fixation, None);
        let flagged = pb::GazeSample {
            fixation: Some(false),
            ..sample
        };
        let back = pb::GazeSample::decode(flagged.encode_to_vec().as_slice()).expect("decodes");
        assert_eq!(
            back.fixation,
            Some(false),
            "optional keeps presence of false"
        );

        let budget = pb::Budget {
            kind: Some(pb::budget::Kind::SphereTests(5000)),
        };
        assert_eq!(
            pb::Budget::decode(budget.encode_to_vec().as_slice()).expect("decodes"),
            budget
        );
    }
}
