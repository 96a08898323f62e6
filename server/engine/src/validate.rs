//! Validation helpers shared by every configuration type: the error that names the field, its value
//! and the accepted range, and the range checks. Kept apart from `config` so that the modules whose
//! types `config` is built from (`perception`, `sphere_tree`) can validate themselves without a
//! cycle back into it.

/// A config field outside its allowed range.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("invalid config: `{field}` = {value}: {expected}")]
pub struct ConfigError {
    /// Dotted path of the offending field, e.g. `scene.shape_radius`.
    pub field: &'static str,
    /// The rejected value, rendered.
    pub value: String,
    /// What would have been accepted.
    pub expected: String,
}

impl ConfigError {
    pub(crate) fn new(
        field: &'static str,
        value: impl std::fmt::Display,
        expected: impl Into<String>,
    ) -> Self {
        Self {
            field,
            value: value.to_string(),
            expected: expected.into(),
        }
    }
}

pub(crate) fn check_finite_positive(field: &'static str, v: f64) -> Result<(), ConfigError> {
    if v.is_finite() && v > 0.0 {
        Ok(())
    } else {
        Err(ConfigError::new(field, v, "must be finite and > 0"))
    }
}

pub(crate) fn check_finite_range(
    field: &'static str,
    v: f64,
    lo: f64,
    hi: f64,
) -> Result<(), ConfigError> {
    if v.is_finite() && (lo..=hi).contains(&v) {
        Ok(())
    } else {
        Err(ConfigError::new(
            field,
            v,
            format!("must be finite and in [{lo}, {hi}]"),
        ))
    }
}
