//! Conversions between engine types and protocol messages.
//!
//! Configure's merge rule lives here: in a request, unset messages and zero or unspecified scalars
//! keep the current value (the protocol cannot tell "0" from "not sent" for proto3 scalars), and a
//! set oneof replaces the whole variant.

use foveal_engine::math::Vec3;
use foveal_engine::narrow_phase::{PairState, PairStatus};
use foveal_engine::shape::Star;
use foveal_engine::{
    BudgetSpec, ConfigError, DeemedTruth, EccentricityUnit, FrameReport, PerceptualFunction,
    PerceptualModel, SchedulerKind, SimConfig, Simulation, TreeKind, Truth,
};
use foveal_proto::pb;

use crate::compare::{Compare, Outcome};
use crate::fixation_cell::{FixationSource, ResolvedFixation};

fn invalid(field: &'static str, value: impl ToString, expected: impl Into<String>) -> ConfigError {
    ConfigError {
        field,
        value: value.to_string(),
        expected: expected.into(),
    }
}

/// Engine scheduler → protocol enum.
pub fn scheduler_to_pb(k: SchedulerKind) -> pb::Scheduler {
    match k {
        SchedulerKind::RoundRobin => pb::Scheduler::RoundRobin,
        SchedulerKind::Sequential => pb::Scheduler::Sequential,
        SchedulerKind::SortedSequential => pb::Scheduler::SortedSequential,
        SchedulerKind::PriorityOnly => pb::Scheduler::PriorityOnly,
        SchedulerKind::PrioritySorted => pb::Scheduler::PrioritySorted,
        SchedulerKind::ExpectedGain => pb::Scheduler::ExpectedGain,
        SchedulerKind::Priced => pb::Scheduler::Priced,
    }
}

/// Protocol enum → engine scheduler; `None` for "unspecified" (keep the current one).
pub fn scheduler_from_pb(raw: i32) -> Result<Option<SchedulerKind>, ConfigError> {
    let k = pb::Scheduler::try_from(raw)
        .map_err(|_| invalid("scheduler", raw, "must be a Scheduler enum value (0..=7)"))?;
    Ok(match k {
        pb::Scheduler::Unspecified => None,
        pb::Scheduler::RoundRobin => Some(SchedulerKind::RoundRobin),
        pb::Scheduler::Sequential => Some(SchedulerKind::Sequential),
        pb::Scheduler::SortedSequential => Some(SchedulerKind::SortedSequential),
        pb::Scheduler::PriorityOnly => Some(SchedulerKind::PriorityOnly),
        pb::Scheduler::PrioritySorted => Some(SchedulerKind::PrioritySorted),
        pb::Scheduler::ExpectedGain => Some(SchedulerKind::ExpectedGain),
        pb::Scheduler::Priced => Some(SchedulerKind::Priced),
    })
}

/// Engine truth → protocol enum.
pub fn truth_to_pb(t: Truth) -> pb::Truth {
    match t {
        Truth::Shape => pb::Truth::Shape,
        Truth::LeafSpheres => pb::Truth::LeafSpheres,
    }
}

/// Engine tree kind → protocol enum.
pub fn tree_to_pb(t: TreeKind) -> pb::Tree {
    match t {
        TreeKind::Parts => pb::Tree::Parts,
        TreeKind::Fitted => pb::Tree::Fitted,
        TreeKind::Octree => pb::Tree::Octree,
    }
}

/// Protocol enum → engine tree kind; `None` for "unspecified" (keep the current one).
pub fn tree_from_pb(raw: i32) -> Result<Option<TreeKind>, ConfigError> {
    let t = pb::Tree::try_from(raw).map_err(|_| {
        invalid(
            "scene.tree",
            raw,
            "must be a Tree enum value: 0 (unspecified, keep), 1 (TREE_PARTS), 2 (TREE_FITTED) or 3 (TREE_OCTREE)",
        )
    })?;
    Ok(match t {
        pb::Tree::Unspecified => None,
        pb::Tree::Parts => Some(TreeKind::Parts),
        pb::Tree::Fitted => Some(TreeKind::Fitted),
        pb::Tree::Octree => Some(TreeKind::Octree),
    })
}

/// Protocol enum → engine truth; `None` for "unspecified" (keep the current one). The error
/// carries the engine's name of the field, as validation does for the other scene fields.
pub fn truth_from_pb(raw: i32) -> Result<Option<Truth>, ConfigError> {
    let t = pb::Truth::try_from(raw).map_err(|_| {
        invalid(
            "scene.truth",
            raw,
            "must be a Truth enum value: 0 (unspecified, keep), 1 (TRUTH_SHAPE) or 2 (TRUTH_LEAF_SPHERES)",
        )
    })?;
    Ok(match t {
        pb::Truth::Unspecified => None,
        pb::Truth::Shape => Some(Truth::Shape),
        pb::Truth::LeafSpheres => Some(Truth::LeafSpheres),
    })
}

/// The star of bounding radius `radius` (GetScene's `star`).
pub fn star_to_pb(radius: f64) -> pb::StarShape {
    let s = Star::new(radius);
    pb::StarShape {
        radius: s.radius,
        core_radius: s.core_radius,
        spike_base_radius: s.spike_base_radius,
    }
}

/// Engine budget → protocol message.
pub fn budget_to_pb(b: BudgetSpec) -> pb::Budget {
    use pb::budget::Kind;
    let kind = match b {
        BudgetSpec::Exact => Kind::Exact(pb::ExactBudget {}),
        BudgetSpec::InterruptAtZero => Kind::InterruptAtZero(true),
        BudgetSpec::WallMs(ms) => Kind::WallMs(ms),
        BudgetSpec::SphereTests(n) => Kind::SphereTests(n),
        BudgetSpec::FractionOfExact(f) => Kind::FractionOfExact(f),
    };
    pb::Budget { kind: Some(kind) }
}

/// Protocol budget → engine budget; `None` when no variant is set (keep the current one).
pub fn budget_from_pb(b: &pb::Budget) -> Result<Option<BudgetSpec>, ConfigError> {
    use pb::budget::Kind;
    Ok(match b.kind {
        None => None,
        Some(Kind::Exact(_)) => Some(BudgetSpec::Exact),
        Some(Kind::InterruptAtZero(true)) => Some(BudgetSpec::InterruptAtZero),
        Some(Kind::InterruptAtZero(false)) => {
            return Err(invalid(
                "budget.interrupt_at_zero",
                false,
                "must be true to select this budget",
            ));
        }
        Some(Kind::WallMs(ms)) => Some(BudgetSpec::WallMs(ms)),
        Some(Kind::SphereTests(n)) => Some(BudgetSpec::SphereTests(n)),
        Some(Kind::FractionOfExact(f)) => Some(BudgetSpec::FractionOfExact(f)),
    })
}

fn unit_to_pb(u: EccentricityUnit) -> pb::EccentricityUnit {
    match u {
        EccentricityUnit::Pixels => pb::EccentricityUnit::Pixels,
        EccentricityUnit::Degrees => pb::EccentricityUnit::Degrees,
    }
}

/// Engine model → protocol message.
pub fn model_to_pb(m: PerceptualModel) -> pb::PerceptualModel {
    use pb::perceptual_model::Model;
    let model = match m.function {
        PerceptualFunction::F1 => Model::F1(pb::ModelF1 {}),
        PerceptualFunction::F2 { c } => Model::F2(pb::ModelF2 { c }),
        PerceptualFunction::F2Range { c_min, c_max } => {
            Model::F2Range(pb::ModelF2Range { c_min, c_max })
        }
        PerceptualFunction::F3 { c1, c2, c3, e1, e2 } => {
            Model::F3(pb::ModelF3 { c1, c2, c3, e1, e2 })
        }
    };
    pb::PerceptualModel {
        model: Some(model),
        eccentricity_unit: unit_to_pb(m.unit) as i32,
    }
}

/// Merge a protocol model into `current`: a set variant replaces the function, a specified unit
/// replaces the unit. The F3 breaks are taken in the model's unit, as the engine evaluates them.
pub fn merge_model(
    field: &'static str,
    current: PerceptualModel,
    m: &pb::PerceptualModel,
) -> Result<PerceptualModel, ConfigError> {
    use pb::perceptual_model::Model;
    let unit = match pb::EccentricityUnit::try_from(m.eccentricity_unit) {
        Ok(pb::EccentricityUnit::Unspecified) => current.unit,
        Ok(pb::EccentricityUnit::Pixels) => EccentricityUnit::Pixels,
        Ok(pb::EccentricityUnit::Degrees) => EccentricityUnit::Degrees,
        Err(_) => {
            return Err(invalid(
                field,
                format!("eccentricity_unit={}", m.eccentricity_unit),
                "must be an EccentricityUnit enum value (0..=2)",
            ));
        }
    };
    let function = match &m.model {
        None => current.function,
        Some(Model::F1(_)) => PerceptualFunction::F1,
        Some(Model::F2(f)) => PerceptualFunction::F2 { c: f.c },
        Some(Model::F2Range(f)) => PerceptualFunction::F2Range {
            c_min: f.c_min,
            c_max: f.c_max,
        },
        Some(Model::F3(f)) => PerceptualFunction::F3 {
            c1: f.c1,
            c2: f.c2,
            c3: f.c3,
            e1: f.e1,
            e2: f.e2,
        },
    };
    let merged = PerceptualModel { function, unit };
    merged.validate(field)?;
    Ok(merged)
}

/// The full protocol view of a configuration (every field filled in).
pub fn scene_config_to_pb(c: &SimConfig, frame_rate_hz: f64) -> pb::SceneConfig {
    let s = &c.scene;
    pb::SceneConfig {
        bodies: s.bodies,
        seed: s.seed,
        density: s.density,
        shape_radius: s.shape_radius,
        depth: s.depth,
        dt_s: s.dt,
        min_speed: s.min_speed,
        max_speed: s.max_speed,
        max_spin: s.max_spin,
        scheduler: scheduler_to_pb(c.scheduler) as i32,
        eccentricity_threshold_deg: c.eccentricity_threshold_deg,
        budget: Some(budget_to_pb(c.budget)),
        schedule_model: Some(model_to_pb(c.schedule_model)),
        measure_model: Some(model_to_pb(c.measure_model)),
        audit: c.audit,
        frame_rate_hz,
        display: Some(pb::Display {
            width_px: c.display.width_px,
            height_px: c.display.height_px,
            diagonal_in: c.display.diagonal_in,
            viewing_distance_cm: c.display.viewing_distance_cm,
        }),
        truth: truth_to_pb(s.truth) as i32,
        compare: pb::Compare::Off as i32,
        tree: tree_to_pb(s.tree) as i32,
    }
}

/// Keep `current` unless the request carries a non-zero value. NaN is "set" (and then refused by
/// validation), so that a NaN never silently means "keep".
fn pick_f64(current: f64, requested: f64) -> f64 {
    if requested == 0.0 { current } else { requested }
}

fn pick<T: PartialEq + Default>(current: T, requested: T) -> T {
    if requested == T::default() {
        current
    } else {
        requested
    }
}

/// Apply a Configure request to the configuration in force and validate the result. Returns the
/// merged simulation config and frame rate; the error names the first offending field.
pub fn merge_scene_config(
    current: &SimConfig,
    current_rate_hz: f64,
    req: &pb::SceneConfig,
) -> Result<(SimConfig, f64), ConfigError> {
    let mut c = current.clone();
    let s = &mut c.scene;
    s.bodies = pick(s.bodies, req.bodies);
    s.seed = pick(s.seed, req.seed);
    s.density = pick_f64(s.density, req.density);
    s.shape_radius = pick_f64(s.shape_radius, req.shape_radius);
    s.depth = pick(s.depth, req.depth);
    s.dt = pick_f64(s.dt, req.dt_s);
    s.min_speed = pick_f64(s.min_speed, req.min_speed);
    s.max_speed = pick_f64(s.max_speed, req.max_speed);
    s.max_spin = pick_f64(s.max_spin, req.max_spin);
    if let Some(t) = truth_from_pb(req.truth)? {
        s.truth = t;
    }
    if let Some(t) = tree_from_pb(req.tree)? {
        s.tree = t;
    }
    if let Some(k) = scheduler_from_pb(req.scheduler)? {
        c.scheduler = k;
    }
    c.eccentricity_threshold_deg =
        pick_f64(c.eccentricity_threshold_deg, req.eccentricity_threshold_deg);
    if let Some(b) = req
        .budget
        .as_ref()
        .map(budget_from_pb)
        .transpose()?
        .flatten()
    {
        c.budget = b;
    }
    if let Some(m) = &req.schedule_model {
        c.schedule_model = merge_model("schedule_model", c.schedule_model, m)?;
    }
    if let Some(m) = &req.measure_model {
        c.measure_model = merge_model("measure_model", c.measure_model, m)?;
    }
    c.audit = req.audit;
    if let Some(d) = &req.display {
        c.display.width_px = pick(c.display.width_px, d.width_px);
        c.display.height_px = pick(c.display.height_px, d.height_px);
        c.display.diagonal_in = pick_f64(c.display.diagonal_in, d.diagonal_in);
        c.display.viewing_distance_cm =
            pick_f64(c.display.viewing_distance_cm, d.viewing_distance_cm);
    }
    let rate = pick_f64(current_rate_hz, req.frame_rate_hz);
    crate::config::validate_frame_rate(rate)?;
    c.validate()?;
    Ok((c, rate))
}

/// Apply a Configure request with an update mask: exactly the listed fields are taken from `req`,
/// zero and false included; the rest keep their current value. The error names the first
/// offending field (or the unknown path).
pub fn merge_masked(
    current: &SimConfig,
    current_rate_hz: f64,
    req: &pb::SceneConfig,
    paths: &[String],
) -> Result<(SimConfig, f64), ConfigError> {
    let mut c = current.clone();
    let mut rate = current_rate_hz;
    let display = req.display.unwrap_or_default();
    for path in paths {
        let s = &mut c.scene;
        match path.as_str() {
            "bodies" => s.bodies = req.bodies,
            "seed" => s.seed = req.seed,
            "density" => s.density = req.density,
            "shape_radius" => s.shape_radius = req.shape_radius,
            "depth" => s.depth = req.depth,
            "dt_s" => s.dt = req.dt_s,
            "min_speed" => s.min_speed = req.min_speed,
            "max_speed" => s.max_speed = req.max_speed,
            "max_spin" => s.max_spin = req.max_spin,
            "tree" => {
                s.tree = tree_from_pb(req.tree)?.ok_or_else(|| {
                    invalid(
                        "scene.tree",
                        "TREE_UNSPECIFIED",
                        "must name a tree when listed in update_mask",
                    )
                })?;
            }
            "truth" => {
                s.truth = truth_from_pb(req.truth)?.ok_or_else(|| {
                    invalid(
                        "scene.truth",
                        "TRUTH_UNSPECIFIED",
                        "must name a truth when listed in update_mask",
                    )
                })?;
            }
            "scheduler" => {
                c.scheduler = scheduler_from_pb(req.scheduler)?.ok_or_else(|| {
                    invalid(
                        "scheduler",
                        "SCHEDULER_UNSPECIFIED",
                        "must name a scheduler when listed in update_mask",
                    )
                })?;
            }
            "eccentricity_threshold_deg" => {
                c.eccentricity_threshold_deg = req.eccentricity_threshold_deg;
            }
            "budget" => {
                c.budget = req
                    .budget
                    .as_ref()
                    .map(budget_from_pb)
                    .transpose()?
                    .flatten()
                    .ok_or_else(|| {
                        invalid(
                            "budget",
                            "unset",
                            "must set one budget kind when listed in update_mask",
                        )
                    })?;
            }
            "schedule_model" => {
                let m = req.schedule_model.unwrap_or_default();
                c.schedule_model = merge_model("schedule_model", c.schedule_model, &m)?;
            }
            "measure_model" => {
                let m = req.measure_model.unwrap_or_default();
                c.measure_model = merge_model("measure_model", c.measure_model, &m)?;
            }
            "audit" => c.audit = req.audit,
            "frame_rate_hz" => rate = req.frame_rate_hz,
            // The server's, not the engine's: `crate::compare::merge` takes it.
            "compare" => {}
            "display" => {
                c.display.width_px = display.width_px;
                c.display.height_px = display.height_px;
                c.display.diagonal_in = display.diagonal_in;
                c.display.viewing_distance_cm = display.viewing_distance_cm;
            }
            "display.width_px" => c.display.width_px = display.width_px,
            "display.height_px" => c.display.height_px = display.height_px,
            "display.diagonal_in" => c.display.diagonal_in = display.diagonal_in,
            "display.viewing_distance_cm" => {
                c.display.viewing_distance_cm = display.viewing_distance_cm;
            }
            other => {
                // The client's string, bounded: it goes into the log line and the status.
                return Err(invalid(
                    "update_mask",
                    crate::limits::excerpt(other, 64),
                    "must list SceneConfig field names (e.g. `bodies`, `audit`, `display.width_px`)",
                ));
            }
        }
    }
    crate::config::validate_frame_rate(rate)?;
    c.validate()?;
    Ok((c, rate))
}

/// The SceneConfig fields that differ between two full configurations (for the Configure log).
pub fn changed_fields(before: &pb::SceneConfig, after: &pb::SceneConfig) -> Vec<&'static str> {
    let mut changed = Vec::new();
    macro_rules! cmp {
        ($($f:ident),*) => {
            $(if before.$f != after.$f { changed.push(stringify!($f)); })*
        };
    }
    cmp!(
        bodies,
        seed,
        density,
        shape_radius,
        depth,
        dt_s,
        min_speed,
        max_speed,
        max_spin,
        scheduler,
        eccentricity_threshold_deg,
        budget,
        schedule_model,
        measure_model,
        audit,
        frame_rate_hz,
        display,
        truth,
        compare,
        tree
    );
    changed
}

fn vec3(v: Vec3) -> pb::Vec3 {
    pb::Vec3 {
        x: v.x,
        y: v.y,
        z: v.z,
    }
}

/// Everything static about `sim`'s scene, for GetScene.
pub fn scene_description(sim: &Simulation, frame_rate_hz: f64) -> pb::SceneDescription {
    let cfg = sim.config();
    let world = sim.world();
    let tree = sim.tree();
    let viewer = sim.viewer();
    let spheres = tree
        .records()
        .into_iter()
        .map(|r| pb::Sphere {
            x: r.center[0] as f32,
            y: r.center[1] as f32,
            z: r.center[2] as f32,
            radius: r.radius as f32,
            level: r.level,
            first_child: r.first_child,
            child_count: r.child_count,
        })
        .collect();
    let spheres_per_level = tree
        .spheres_per_level()
        .into_iter()
        .map(|n| u32::try_from(n).unwrap_or(u32::MAX))
        .collect();
    pb::SceneDescription {
        config: Some(scene_config_to_pb(cfg, frame_rate_hz)),
        volume_side: cfg.scene.volume_side(),
        volume_origin: Some(vec3(world.lo)),
        tree: Some(pb::SphereTree {
            spheres,
            spheres_per_level,
        }),
        camera: Some(pb::Camera {
            eye: Some(vec3(viewer.eye)),
            target: Some(vec3(viewer.target)),
            fov_y_deg: viewer.fov_y_deg,
            aspect: f64::from(viewer.display.width_px) / f64::from(viewer.display.height_px),
        }),
        star: Some(star_to_pb(cfg.scene.shape_radius)),
    }
}

/// Body poses packed as f32, positions relative to the volume's minimum corner (f32 keeps about
/// 1e-7 relative precision near the volume however far the scene sits from the world origin).
pub fn poses(sim: &Simulation) -> pb::Poses {
    let w = sim.world();
    // Body i of the message is body id i, wherever the engine keeps it.
    let slots = sim.body_slots();
    pb::Poses::pack(
        vec3(w.lo),
        slots
            .iter()
            .map(|&s| (w.position[s as usize] - w.lo).as_vec3().to_array()),
        slots
            .iter()
            .map(|&s| w.orientation[s as usize].as_quat().to_array()),
    )
}

/// The current poses quantised for viewers (WatchFramesRequest.quantised_poses).
pub fn quantised_poses(sim: &Simulation) -> pb::QuantisedPoses {
    let w = sim.world();
    let extent = (w.hi - w.lo).max_element();
    let slots = sim.body_slots();
    pb::QuantisedPoses::pack(
        vec3(w.lo),
        extent,
        slots
            .iter()
            .map(|&s| (w.position[s as usize] - w.lo).as_vec3().to_array()),
        slots
            .iter()
            .map(|&s| w.orientation[s as usize].as_quat().to_array()),
    )
}

/// The last frame's collision list: pairs resolved as colliding and pairs deemed colliding, with
/// the frame's audit of the deemed ones, or else `paired` (the side by side's audit of them).
pub fn collisions(sim: &Simulation, paired: Option<&[DeemedTruth]>) -> pb::Collisions {
    let own = sim.deemed_truth();
    let truth = if own.is_empty() {
        paired.unwrap_or(&[])
    } else {
        own
    };
    collision_list(sim, sim.pairs(), truth)
}

/// A collision list of `pairs` (states of `sim`'s candidates), by body id, with `truth` (one
/// answer a deemed pair, in order, or none).
pub fn collision_list(
    sim: &Simulation,
    pairs: &[PairState],
    truth: &[DeemedTruth],
) -> pb::Collisions {
    let of = |status: PairStatus| {
        pairs
            .iter()
            .filter(move |p| p.status == status)
            .map(|p| sim.id_pair((p.a, p.b)))
    };
    pb::Collisions::pack(of(PairStatus::Colliding), of(PairStatus::Deemed))
        .with_deemed_truth(truth.iter().map(|&t| t as u8))
}

/// The protocol fixation of a frame.
pub fn fixation_to_pb(f: &ResolvedFixation) -> pb::Fixation {
    pb::Fixation {
        x: f.fixation.x,
        y: f.fixation.y,
        age_s: f.fixation.age_s,
        source: fixation_source_to_pb(f.source) as i32,
        raw: f.raw.map(|r| pb::RawGaze {
            x: r.x,
            y: r.y,
            age_s: r.age_s,
            tracker_time_s: r.tracker_time_s,
        }),
        track: gaze_track_to_pb(f.track) as i32,
        widen_deg: f.widen_deg,
    }
}

/// The protocol's name for where a frame's fixation came from.
pub fn fixation_source_to_pb(source: FixationSource) -> pb::FixationSource {
    match source {
        FixationSource::Gaze => pb::FixationSource::Gaze,
        FixationSource::FallbackNoGaze => pb::FixationSource::FallbackNoGaze,
        FixationSource::FallbackStale => pb::FixationSource::FallbackStale,
        FixationSource::FallbackTrackLost => pb::FixationSource::FallbackTrackLost,
    }
}

/// The protocol's name for what the gaze processing steered by.
pub fn gaze_track_to_pb(track: foveal_gaze::online::Track) -> pb::GazeTrack {
    use foveal_gaze::online::Track;
    match track {
        Track::NoGaze => pb::GazeTrack::NoGaze,
        Track::Raw => pb::GazeTrack::Raw,
        Track::Fixation => pb::GazeTrack::Fixation,
        Track::Saccade => pb::GazeTrack::Saccade,
        Track::Holding => pb::GazeTrack::Holding,
        Track::Widened => pb::GazeTrack::Widened,
        Track::Lost => pb::GazeTrack::Lost,
    }
}

/// The fixation a step used, from the engine's record of it, with the source the server resolved
/// and what the gaze processing saw. The engine ignores an unusable fixation; the frame then says
/// the centre was used for want of gaze rather than repeating what was handed in.
pub fn fixation_used(r: &FrameReport, resolved: &ResolvedFixation) -> pb::Fixation {
    let base = fixation_to_pb(resolved);
    match r.fixation {
        Some(f) => pb::Fixation {
            x: f.x,
            y: f.y,
            age_s: f.age_s,
            widen_deg: f.uncertainty_deg,
            ..base
        },
        None => pb::Fixation {
            x: crate::fixation_cell::FALLBACK.0,
            y: crate::fixation_cell::FALLBACK.1,
            age_s: 0.0,
            source: fixation_source_to_pb(FixationSource::FallbackNoGaze) as i32,
            widen_deg: 0.0,
            ..base
        },
    }
}

fn ns_to_s(ns: u64) -> f64 {
    ns as f64 * 1e-9
}

/// The side by side's part of a frame: the second collider's metrics (with its audit) and time.
pub fn comparison_to_pb(kind: Compare, out: &Outcome) -> pb::Comparison {
    let report = FrameReport {
        audit: Some(out.audit.blind),
        ..out.report.clone()
    };
    let metrics = frame_to_pb(&report, 0, &pb::Fixation::default()).metrics;
    pb::Comparison {
        collider: kind.to_pb() as i32,
        metrics,
        run_s: ns_to_s(out.run_ns),
        collisions: None,
        main_audit: Some(audit_to_pb(&out.audit.main)),
        audit_stride: out.audit.stride,
    }
}

/// The protocol's audit of a frame.
fn audit_to_pb(a: &foveal_engine::AuditReport) -> pb::AuditMetrics {
    pb::AuditMetrics {
        true_false_positives: u64::from(a.false_positives),
        true_geometric_inaccuracy: a.geometric_inaccuracy,
        true_perceived_inaccuracy: a.perceived_inaccuracy.unwrap_or(0.0),
        true_foveal_false_positives: u64::from(a.foveal_false_positives),
    }
}

/// A frame without poses or collisions and with `dropped_before` 0 (all are per subscriber).
pub fn frame_to_pb(r: &FrameReport, index: u64, fixation: &pb::Fixation) -> pb::Frame {
    let p = &r.profile;
    pb::Frame {
        index,
        sim_time_s: r.sim_time,
        fixation: Some(*fixation),
        metrics: Some(pb::FrameMetrics {
            collision_time_s: r.collision_time_s(),
            geometric_inaccuracy: r.geometric_inaccuracy,
            perceived_inaccuracy: r.perceived_inaccuracy.unwrap_or(0.0),
            candidate_pairs: u64::from(r.candidate_pairs),
            real_collisions: u64::from(r.real_collisions),
            deemed_at_interruption: u64::from(r.deemed),
            resolved_per_level: r.resolved_per_level.iter().map(|&n| u64::from(n)).collect(),
            sphere_tests: r.sphere_tests,
            budget_exhausted: r.budget_exhausted,
            metrics_stride: r.metrics_stride,
            geometric_inaccuracy_se: r.geometric_inaccuracy_se,
            perceived_inaccuracy_se: r.perceived_inaccuracy_se.unwrap_or(0.0),
            budget_spent_before_narrow: r.budget_spent_before_narrow,
            foveal_pairs: u64::from(r.foveal_pairs),
            foveal_deemed: u64::from(r.foveal_deemed),
            audit: r.audit.as_ref().map(audit_to_pb),
        }),
        profile: Some(pb::PhaseProfile {
            integrate_s: ns_to_s(p.integrate_ns),
            broad_s: ns_to_s(p.broad_ns),
            narrow_s: ns_to_s(p.narrow_ns),
            response_s: ns_to_s(p.response_ns),
            prioritise_s: ns_to_s(p.prioritise_ns),
            measure_s: ns_to_s(p.measure_ns),
            renumber_s: ns_to_s(p.renumber_ns),
        }),
        dropped_before: 0,
        poses: None,
        quantised_poses: None,
        collisions: None,
        comparison: None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fixation_sources_keep_their_wire_values_and_recorded_names() {
        for (source, wire, recorded) in [
            (FixationSource::Gaze, 1, "gaze"),
            (FixationSource::FallbackNoGaze, 2, "fallback_no_gaze"),
            (FixationSource::FallbackStale, 3, "fallback_stale"),
            (FixationSource::FallbackTrackLost, 4, "fallback_track_lost"),
        ] {
            let pb_source = fixation_source_to_pb(source);
            assert_eq!(pb_source as i32, wire, "{source:?}");
            assert_eq!(source.name(), recorded, "{source:?}");
            assert_eq!(
                pb_source.as_str_name(),
                format!("FIXATION_SOURCE_{}", recorded.to_uppercase()),
                "a recorded name is the protocol's"
            );
        }
    }

    #[test]
    fn config_round_trips_and_empty_request_keeps_everything() {
        let c = SimConfig {
            budget: BudgetSpec::SphereTests(1234),
            scheduler: SchedulerKind::RoundRobin,
            measure_model: PerceptualModel::f1_pixels(),
            ..SimConfig::default()
        };
        let pbc = scene_config_to_pb(&c, 90.0);
        let (back, rate) = merge_scene_config(&SimConfig::default(), 60.0, &pbc).expect("valid");
        assert_eq!(back, c);
        assert_eq!(rate, 90.0);
        let (same, rate) =
            merge_scene_config(&c, 90.0, &pb::SceneConfig::default()).expect("valid");
        assert_eq!(same, c);
        assert_eq!(rate, 90.0);
    }

    #[test]
    fn a_mask_applies_exactly_its_fields_and_the_log_names_them() {
        let c = SimConfig::default();
        let paths = |p: &[&str]| p.iter().map(|&s| s.to_owned()).collect::<Vec<_>>();
        let req = pb::SceneConfig {
            seed: 0,
            min_speed: 0.0,
            bodies: 7,
            ..Default::default()
        };
        let (m, rate) =
            merge_masked(&c, 60.0, &req, &paths(&["seed", "min_speed"])).expect("valid");
        assert_eq!((m.scene.seed, m.scene.min_speed), (0, 0.0));
        assert_eq!(
            m.scene.bodies, c.scene.bodies,
            "unlisted fields keep their value"
        );
        assert_eq!(rate, 60.0);
        let changed = changed_fields(&scene_config_to_pb(&c, 60.0), &scene_config_to_pb(&m, rate));
        assert_eq!(changed, ["seed", "min_speed"]);
        let e = merge_masked(&c, 60.0, &req, &paths(&["budget"])).expect_err("no budget set");
        assert_eq!(e.field, "budget");
        let e = merge_masked(&c, 60.0, &req, &paths(&["colour"])).expect_err("unknown path");
        assert_eq!(e.field, "update_mask");
        let long = "x".repeat(1 << 20);
        let e = merge_masked(&c, 60.0, &req, &paths(&[long.as_str()])).expect_err("unknown path");
        assert!(
            e.value.len() < 100,
            "a client's path is quoted bounded: {} bytes",
            e.value.len()
        );
    }

    #[test]
    fn merge_errors_name_the_field() {
        let c = SimConfig::default();
        let field = |req: pb::SceneConfig| merge_scene_config(&c, 60.0, &req).map_err(|e| e.field);
        assert_eq!(
            field(pb::SceneConfig {
                bodies: 3_000_000,
                ..Default::default()
            }),
            Err("scene.bodies")
        );
        assert_eq!(
            field(pb::SceneConfig {
                density: f64::NAN,
                ..Default::default()
            }),
            Err("scene.density")
        );
        assert_eq!(
            field(pb::SceneConfig {
                frame_rate_hz: 1e6,
                ..Default::default()
            }),
            Err("frame_rate_hz")
        );
        assert_eq!(
            field(pb::SceneConfig {
                scheduler: 42,
                ..Default::default()
            }),
            Err("scheduler")
        );
        assert_eq!(
            field(pb::SceneConfig {
                budget: Some(pb::Budget {
                    kind: Some(pb::budget::Kind::WallMs(-3.0))
                }),
                ..Default::default()
            }),
            Err("budget.wall_ms")
        );
        assert_eq!(
            field(pb::SceneConfig {
                measure_model: Some(pb::PerceptualModel {
                    model: Some(pb::perceptual_model::Model::F2(pb::ModelF2 { c: -1.0 })),
                    eccentricity_unit: 0,
                }),
                ..Default::default()
            }),
            Err("measure_model")
        );
    }

    #[test]
    fn truth_goes_both_ways_unspecified_keeps_it_and_out_of_range_is_refused() {
        assert_eq!(truth_from_pb(pb::Truth::Unspecified as i32), Ok(None));
        for t in Truth::ALL {
            assert_eq!(truth_from_pb(truth_to_pb(t) as i32), Ok(Some(t)));
            let mut c = SimConfig::default();
            c.scene.truth = t;
            let pbc = scene_config_to_pb(&c, 60.0);
            assert_eq!(pbc.truth, truth_to_pb(t) as i32);
            let (back, _) = merge_scene_config(&SimConfig::default(), 60.0, &pbc).expect("valid");
            assert_eq!(back.scene.truth, t);
        }
        assert_eq!(
            scene_config_to_pb(&SimConfig::default(), 60.0).truth,
            pb::Truth::Shape as i32,
            "the default is the drawn shape"
        );

        let leaf = pb::SceneConfig {
            truth: pb::Truth::LeafSpheres as i32,
            ..Default::default()
        };
        let c = SimConfig::default();
        let (m, _) = merge_scene_config(&c, 60.0, &leaf).expect("valid");
        assert_eq!(m.scene.truth, Truth::LeafSpheres);
        let changed = changed_fields(&scene_config_to_pb(&c, 60.0), &scene_config_to_pb(&m, 60.0));
        assert_eq!(changed, ["truth"]);
        let (kept, _) = merge_scene_config(&m, 60.0, &pb::SceneConfig::default()).expect("valid");
        assert_eq!(kept.scene.truth, Truth::LeafSpheres, "unspecified keeps it");

        let paths = ["truth".to_owned()];
        let shape = pb::SceneConfig {
            truth: pb::Truth::Shape as i32,
            ..Default::default()
        };
        let (masked, _) = merge_masked(&m, 60.0, &shape, &paths).expect("valid");
        assert_eq!(masked.scene.truth, Truth::Shape);
        let e = merge_masked(&m, 60.0, &pb::SceneConfig::default(), &paths)
            .expect_err("a listed truth must be named");
        assert_eq!(e.field, "scene.truth");

        for raw in [7, -1, 3] {
            let bad = pb::SceneConfig {
                truth: raw,
                ..Default::default()
            };
            let e = merge_scene_config(&c, 60.0, &bad).expect_err("out of range");
            assert_eq!(
                (e.field, e.value.as_str()),
                ("scene.truth", raw.to_string().as_str())
            );
            assert!(e.expected.contains("TRUTH_LEAF_SPHERES"), "{e}");
            let e = merge_masked(&c, 60.0, &bad, &paths).expect_err("out of range");
            assert_eq!(e.field, "scene.truth");
        }
    }

    #[test]
    fn the_scene_description_carries_the_truth_and_the_star() {
        let mut c = SimConfig::default();
        c.scene.bodies = 20;
        c.scene.shape_radius = 0.5;
        c.scene.truth = Truth::LeafSpheres;
        let sim = Simulation::new(c).expect("valid");
        let d = scene_description(&sim, 60.0);
        assert_eq!(
            d.config.expect("config").truth,
            pb::Truth::LeafSpheres as i32
        );
        let star = d.star.expect("star");
        assert_eq!(star.radius, 0.5);
        assert!((star.core_radius - 0.15).abs() < 1e-12, "{star:?}");
        assert!((star.spike_base_radius - 0.125).abs() < 1e-12, "{star:?}");
    }

    #[test]
    fn poses_are_relative_to_the_origin() {
        let mut c = SimConfig::default();
        c.scene = foveal_engine::SceneConfig {
            bodies: 20,
            origin: [100.0, -50.0, 3.0],
            ..c.scene
        };
        let sim = Simulation::new(c).expect("valid");
        let p = poses(&sim);
        assert_eq!(
            (p.bodies, p.positions.len(), p.orientations.len()),
            (20, 240, 320)
        );
        let o = p.origin.expect("origin");
        assert_eq!((o.x, o.y, o.z), (100.0, -50.0, 3.0));
        let side = sim.config().scene.volume_side() as f32;
        assert!(
            p.positions_f32()
                .flatten()
                .all(|v| (0.0..=side).contains(&v))
        );
        let q = sim.world().orientation[3].as_quat().to_array();
        assert_eq!(p.orientations_f32().nth(3), Some(q));
        let d = scene_description(&sim, 60.0);
        assert_eq!(d.tree.expect("tree").spheres_per_level, vec![1, 7, 20, 80]);
    }
}
