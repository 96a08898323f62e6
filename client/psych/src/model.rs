//! The perceptual functions of the paper's section 3 and the observer whose responses they
//! predict (the crate's doc gives the model).

use std::fmt;

/// A perceptual function F(g, e) of the gap `g` and its eccentricity `e`, both in degrees of
/// visual angle (section 3 of the paper).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Function {
    /// F1 = g / e, and g at e = 0: a steep, "tunnel vision" fall-off.
    F1,
    /// F2 = g / exp(e / C).
    F2 {
        /// Fall-off constant C (degrees).
        c: f64,
    },
    /// F2 with C piecewise in e: C1 below `e1`, C2 below `e2`, C3 beyond (the breaks are part
    /// of the design, not fitted).
    F3 {
        /// C below `e1`.
        c1: f64,
        /// C from `e1` to `e2`.
        c2: f64,
        /// C beyond `e2`.
        c3: f64,
        /// First break (degrees).
        e1: f64,
        /// Second break (degrees).
        e2: f64,
    },
}

impl Function {
    /// F(g, e).
    pub fn strength(&self, g: f64, e: f64) -> f64 {
        match *self {
            Self::F1 => {
                if e > 0.0 {
                    g / e
                } else {
                    g
                }
            }
            Self::F2 { c } => g * (-e / c).exp(),
            Self::F3 { c1, c2, c3, e1, e2 } => {
                let c = if e < e1 {
                    c1
                } else if e < e2 {
                    c2
                } else {
                    c3
                };
                g * (-e / c).exp()
            }
        }
    }

    /// The fitted constants: none for F1, C for F2, C1..C3 for F3.
    pub fn constants(&self) -> Vec<f64> {
        match *self {
            Self::F1 => Vec::new(),
            Self::F2 { c } => vec![c],
            Self::F3 { c1, c2, c3, .. } => vec![c1, c2, c3],
        }
    }

    /// The same function with its constants replaced by `k` (as many as [`Self::constants`]).
    pub fn with_constants(&self, k: &[f64]) -> Self {
        match *self {
            Self::F1 => Self::F1,
            Self::F2 { .. } => Self::F2 { c: k[0] },
            Self::F3 { e1, e2, .. } => Self::F3 {
                c1: k[0],
                c2: k[1],
                c3: k[2],
                e1,
                e2,
            },
        }
    }

    /// Its name in reports: `F1`, `F2` or `F3`.
    pub fn name(&self) -> &'static str {
        match self {
            Self::F1 => "F1",
            Self::F2 { .. } => "F2",
            Self::F3 { .. } => "F3",
        }
    }
}

/// The model string foveal's `--schedule-model` and `--measure-model` take, in degrees.
impl fmt::Display for Function {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Self::F1 => write!(f, "f1:deg"),
            Self::F2 { c } => write!(f, "f2:{}:deg", round4(c)),
            Self::F3 { c1, c2, c3, e1, e2 } => write!(
                f,
                "f3:{},{},{},{},{}:deg",
                round4(c1),
                round4(c2),
                round4(c3),
                round4(e1),
                round4(e2)
            ),
        }
    }
}

/// Four significant digits: a fitted constant is not known better, and the string stays short.
fn round4(x: f64) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    let scale = 10f64.powi(3 - x.abs().log10().floor() as i32);
    (x * scale).round() / scale
}

/// An observer: a perceptual function and the psychometric function over its strength.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Observer {
    /// The perceptual function.
    pub function: Function,
    /// Weibull threshold α on the function's strength (degrees of gap at the fovea).
    pub alpha: f64,
    /// Weibull slope β.
    pub beta: f64,
    /// Guess (false-alarm) rate γ: "apart" for touching bodies.
    pub guess: f64,
    /// Lapse rate λ: "touching" for a gap far above threshold.
    pub lapse: f64,
}

impl Observer {
    /// The probability of reporting "apart" for gap `g` at eccentricity `e` (degrees).
    pub fn p_apart(&self, g: f64, e: f64) -> f64 {
        if g <= 0.0 {
            return self.guess;
        }
        let x = self.function.strength(g, e) / self.alpha;
        let w = -(-x.powf(self.beta)).exp_m1();
        self.guess + (1.0 - self.guess - self.lapse) * w
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn f2_halves_every_c_ln2_degrees() {
        let f = Function::F2 { c: 5.0 };
        let half = 5.0 * std::f64::consts::LN_2;
        assert!((f.strength(1.0, half) - 0.5).abs() < 1e-12);
        assert_eq!(Function::F1.strength(2.0, 4.0), 0.5);
    }

    #[test]
    fn the_observer_runs_from_guess_to_one_minus_lapse() {
        let o = Observer {
            function: Function::F2 { c: 5.0 },
            alpha: 0.1,
            beta: 2.0,
            guess: 0.1,
            lapse: 0.05,
        };
        assert_eq!(o.p_apart(0.0, 3.0), 0.1);
        assert!((o.p_apart(1e-6, 0.0) - 0.1).abs() < 1e-6);
        assert!((o.p_apart(100.0, 0.0) - 0.95).abs() < 1e-9);
        // At threshold the Weibull has risen 1 - 1/e of the way.
        let at = o.p_apart(0.1, 0.0);
        assert!((at - (0.1 + 0.85 * (1.0 - (-1f64).exp()))).abs() < 1e-12);
    }

    #[test]
    fn model_strings_are_what_the_server_parses() {
        assert_eq!(Function::F2 { c: 3.456_78 }.to_string(), "f2:3.457:deg");
        assert_eq!(Function::F1.to_string(), "f1:deg");
        let f3 = Function::F3 {
            c1: 1.0,
            c2: 2.0,
            c3: 4.0,
            e1: 2.5,
            e2: 10.0,
        };
        assert_eq!(f3.to_string(), "f3:1,2,4,2.5,10:deg");
    }
}
