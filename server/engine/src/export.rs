//! A frame as JSON, for offline checks and plotting: config, shape, sphere tree, every body's pose,
//! the candidate pairs and the exact colliding pairs. The engine only builds the text; writing it
//! anywhere is the caller's business.

use serde::Serialize;

use crate::config::SimConfig;
use crate::shape::Star;
use crate::simulation::Simulation;
use crate::sphere_tree::SphereRecord;

#[derive(Serialize)]
struct Body {
    position: [f64; 3],
    /// Unit quaternion, (x, y, z, w).
    orientation: [f64; 4],
}

#[derive(Serialize)]
struct Export<'a> {
    format: &'static str,
    frame_index: u64,
    sim_time: f64,
    config: &'a SimConfig,
    volume_lo: [f64; 3],
    volume_hi: [f64; 3],
    shape: Star,
    box_half_size: f64,
    spheres_per_level: Vec<usize>,
    sphere_tree: Vec<SphereRecord>,
    bodies: Vec<Body>,
    candidate_pairs: Vec<(u32, u32)>,
    exact_colliding_pairs: Vec<(u32, u32)>,
}

impl Simulation {
    /// The current state as pretty-printed JSON (format `foveal.scene.v1`).
    pub fn export_json(&self) -> String {
        let w = self.world();
        let last = self.last_report();
        let e = Export {
            format: "foveal.scene.v1",
            frame_index: last.index,
            sim_time: last.sim_time,
            config: self.config(),
            volume_lo: w.lo.to_array(),
            volume_hi: w.hi.to_array(),
            shape: self.tree().shape(),
            box_half_size: self.tree().root_radius(),
            spheres_per_level: self.tree().spheres_per_level(),
            sphere_tree: self.tree().records(),
            // Bodies in id order and pairs by id, wherever the engine keeps each body.
            bodies: self
                .body_slots()
                .iter()
                .map(|&s| Body {
                    position: w.position[s as usize].to_array(),
                    orientation: w.orientation[s as usize].to_array(),
                })
                .collect(),
            candidate_pairs: self
                .candidate_pairs()
                .iter()
                .map(|&p| self.id_pair(p))
                .collect(),
            exact_colliding_pairs: self
                .exact_colliding_pairs()
                .into_iter()
                .map(|p| self.id_pair(p))
                .collect(),
        };
        // Serialising plain data with finite floats cannot fail; NaN would be written as null.
        serde_json::to_string_pretty(&e).unwrap_or_else(|err| format!("{{\"error\":\"{err}\"}}"))
    }
}
