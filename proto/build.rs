//! Compiles `foveal/v1/*.proto` with protox (pure Rust, no system `protoc`), writes the
//! descriptor set to `$OUT_DIR/foveal_descriptor.bin` for gRPC reflection, and generates the
//! message types and tonic client/server code from that same descriptor set.

use std::path::PathBuf;

use prost::Message;

const PROTOS: &[&str] = &["foveal/v1/foveal.proto"];
const INCLUDES: &[&str] = &["."];

fn main() -> Result<(), Box<dyn std::error::Error>> {
    for proto in PROTOS {
        println!("cargo:rerun-if-changed={proto}");
    }
    println!("cargo:rerun-if-changed=foveal");

    let fds = protox::compile(PROTOS, INCLUDES)?;
    let out_dir = PathBuf::from(std::env::var_os("OUT_DIR").ok_or("OUT_DIR is not set")?);
    std::fs::write(out_dir.join("foveal_descriptor.bin"), fds.encode_to_vec())?;

    tonic_prost_build::configure()
        // Pose buffers are `bytes::Bytes`: cloning a frame for each subscriber shares them.
        .bytes(".foveal.v1.Poses")
        .bytes(".foveal.v1.QuantisedPoses")
        .bytes(".foveal.v1.Collisions")
        .build_client(true)
        .build_server(true)
        .compile_fds(fds)?;
    Ok(())
}
