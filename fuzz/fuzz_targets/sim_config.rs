//! Simulation configs as JSON (the serde form of `SimConfig`): parsing and validation never panic,
//! and a config that validates builds a simulation that runs a frame with finite metrics, under
//! each truth (`scene.truth`, `"shape"` or `"leaf-spheres"`): a mutated JSON text seldom spells
//! the field, so every valid config runs under both.
#![no_main]
use foveal_engine::{FrozenClock, SimConfig, Simulation, Truth};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(cfg) = serde_json::from_slice::<SimConfig>(data) else { return };
    if cfg.validate().is_err() {
        return;
    }
    // Keep each input cheap: large scenes are valid but slow, not interesting here.
    if cfg.scene.bodies > 200 || cfg.scene.depth > 4 || cfg.calibration_frames > 5 {
        return;
    }
    for truth in Truth::ALL {
        let mut cfg = cfg.clone();
        cfg.scene.truth = truth;
        let mut sim = Simulation::new(cfg).expect("a validated config builds");
        let r = sim.step(None, &FrozenClock);
        assert!(r.geometric_inaccuracy.is_finite());
        assert!(sim.world().position.iter().all(|p| p.is_finite()));
    }
});
