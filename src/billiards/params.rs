//! [`BallParams`]: a billiard ball's physical parameters, with pooltool 0.6.0's defaults.

use crate::error::{InputError, InputErrorKind, check_friction, finite};

/// A billiard ball's parameters and the physical constants its motion uses: pooltool 0.6.0's
/// `BallParams`, field for field (pooltool's `m` and `R` are [`mass`](Self::mass) and
/// [`radius`](Self::radius) here).
///
/// Any consistent units (pooltool's are SI: kg, m, s). [`Default`] is pooltool's default, its
/// generic pool ball; [`snooker`](Self::snooker) and [`carom`](Self::carom) are its other
/// prebuilt sets. A `BallParams` is plain data: [`check`](Self::check) says whether it is
/// valid, and the functions that build something from it ([`ball_path`]) call it. Not every
/// field is used by every model (the motion uses `radius`, the three frictions of the cloth
/// and `g`; `u_b`, `e_b`, `e_c` and `f_c` are for the collisions).
///
/// ```
/// use ballcollide::billiards::BallParams;
/// let pool = BallParams::default();
/// assert_eq!((pool.mass, pool.radius, pool.u_s, pool.u_r), (0.170097, 0.028575, 0.2, 0.01));
/// assert_eq!(pool.u_sp(), 4.0 / 9.0 * 0.028575); // spinning friction: proportional to R
/// assert_eq!(BallParams::snooker().u_s, 0.5);
/// pool.check()?;
/// # Ok::<(), ballcollide::InputError>(())
/// ```
///
/// [`ball_path`]: super::ball_path
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BallParams {
    /// The mass (pooltool's `m`).
    pub mass: f64,
    /// The radius (pooltool's `R`).
    pub radius: f64,
    /// The coefficient of sliding friction between ball and cloth.
    pub u_s: f64,
    /// The coefficient of rolling friction.
    pub u_r: f64,
    /// The coefficient of spinning friction divided by the radius: the spinning friction is
    /// [`u_sp`](Self::u_sp) `= u_sp_proportionality · radius`.
    pub u_sp_proportionality: f64,
    /// The coefficient of sliding friction between two balls.
    pub u_b: f64,
    /// The coefficient of restitution between two balls.
    pub e_b: f64,
    /// The coefficient of restitution between a ball and a cushion.
    pub e_c: f64,
    /// The coefficient of friction between a ball and a cushion.
    pub f_c: f64,
    /// The acceleration of gravity.
    pub g: f64,
}

/// pooltool's `u_sp_proportionality`, `10 * 2 / 5 / 9`, evaluated as Python does (left to
/// right in float64): 4/9 rounded once.
const U_SP_PROPORTIONALITY: f64 = 10.0 * 2.0 / 5.0 / 9.0;

impl Default for BallParams {
    /// pooltool's `BallParams()`, its generic pool ball (`POOL_GENERIC`, the default of
    /// 8-ball and 9-ball).
    fn default() -> Self {
        Self {
            mass: 0.170097,
            radius: 0.028575,
            u_s: 0.2,
            u_r: 0.01,
            u_sp_proportionality: U_SP_PROPORTIONALITY,
            u_b: 0.05,
            e_b: 0.95,
            e_c: 0.85,
            f_c: 0.2,
            g: 9.81,
        }
    }
}

impl BallParams {
    /// pooltool's `SNOOKER_GENERIC` (its default for snooker): a lighter, smaller ball on a
    /// grippier cloth and cushion.
    ///
    /// ```
    /// use ballcollide::billiards::BallParams;
    /// let s = BallParams::snooker();
    /// assert_eq!((s.mass, s.radius, s.u_s, s.f_c), (0.140, 0.02619375, 0.5, 0.5));
    /// ```
    pub fn snooker() -> Self {
        Self {
            mass: 0.140,
            radius: 0.02619375,
            u_s: 0.5,
            f_c: 0.5,
            ..Self::default()
        }
    }

    /// pooltool's `BILLIARD_GENERIC` (its default for three-cushion): a carom ball, 61.5 mm
    /// across.
    ///
    /// ```
    /// use ballcollide::billiards::BallParams;
    /// let c = BallParams::carom();
    /// assert_eq!((c.mass, c.radius, c.f_c), (0.210, 0.0615 / 2.0, 0.15));
    /// ```
    pub fn carom() -> Self {
        Self {
            mass: 0.210,
            radius: 0.0615 / 2.0,
            f_c: 0.15,
            ..Self::default()
        }
    }

    /// The coefficient of spinning friction, `u_sp_proportionality · radius` (pooltool's
    /// `u_sp` property, the same product), example: [`BallParams`].
    pub fn u_sp(&self) -> f64 {
        self.u_sp_proportionality * self.radius
    }

    /// Checks the parameters: every number finite, `mass` and `radius` `> 0`, the frictions
    /// (`u_s`, `u_r`, `u_sp_proportionality`, `u_b`, `f_c`) `≥ 0`, `g > 0`, the restitutions
    /// `e_b` and `e_c` in `[0, 1]`.
    ///
    /// pooltool refuses frictions of 0; here a friction of 0 is a state that never ends (a
    /// slide, a roll or a spin lasting for ever), as pooltool's transition times make it.
    ///
    /// # Errors
    /// An [`InputError`] naming the first offending field.
    ///
    /// ```
    /// use ballcollide::billiards::BallParams;
    /// use ballcollide::InputErrorKind;
    /// let bad = BallParams { u_r: -0.01, ..BallParams::default() };
    /// let err = bad.check().unwrap_err();
    /// assert_eq!((err.argument(), err.kind()), ("u_r", InputErrorKind::NegativeFriction(-0.01)));
    /// let err = BallParams { e_b: 1.5, ..BallParams::default() }.check().unwrap_err();
    /// assert_eq!(err.to_string(), "e_b: must be in [0, 1], got 1.5");
    /// ```
    pub fn check(&self) -> Result<(), InputError> {
        positive("mass", self.mass, InputErrorKind::NonPositiveMass)?;
        positive("radius", self.radius, InputErrorKind::NonPositiveBallRadius)?;
        check_friction("u_s", self.u_s)?;
        check_friction("u_r", self.u_r)?;
        check_friction("u_sp_proportionality", self.u_sp_proportionality)?;
        check_friction("u_b", self.u_b)?;
        unit_interval("e_b", self.e_b)?;
        unit_interval("e_c", self.e_c)?;
        check_friction("f_c", self.f_c)?;
        positive("g", self.g, InputErrorKind::NonPositiveGravity)
    }
}

/// `Ok` if `x` is finite and `> 0`, else an error naming `argument` (`kind` for `x ≤ 0`).
fn positive(
    argument: &'static str,
    x: f64,
    kind: fn(f64) -> InputErrorKind,
) -> Result<(), InputError> {
    if finite(argument, x)? > 0.0 {
        Ok(())
    } else {
        Err(InputError::new(argument, kind(x)))
    }
}

/// `Ok` if `x` lies in `[0, 1]`, else an error naming `argument`.
fn unit_interval(argument: &'static str, x: f64) -> Result<(), InputError> {
    if (0.0..=1.0).contains(&x) {
        Ok(())
    } else {
        Err(InputError::new(
            argument,
            InputErrorKind::NotInUnitInterval(x),
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pooltool_defaults() {
        // pooltool: u_sp_proportionality = 10 * 2 / 5 / 9 (Python floats, left to right).
        assert_eq!(U_SP_PROPORTIONALITY, 0.4444444444444444);
        for params in [
            BallParams::default(),
            BallParams::snooker(),
            BallParams::carom(),
        ] {
            params.check().unwrap();
            assert_eq!((params.u_r, params.g, params.e_c), (0.01, 9.81, 0.85));
        }
    }

    #[test]
    fn every_field_is_checked() {
        let base = BallParams::default();
        let cases: [(&str, BallParams); 12] = [
            ("mass", BallParams { mass: 0.0, ..base }),
            (
                "radius",
                BallParams {
                    radius: -1.0,
                    ..base
                },
            ),
            (
                "u_s",
                BallParams {
                    u_s: f64::NAN,
                    ..base
                },
            ),
            ("u_r", BallParams { u_r: -1.0, ..base }),
            (
                "u_sp_proportionality",
                BallParams {
                    u_sp_proportionality: -1.0,
                    ..base
                },
            ),
            (
                "u_b",
                BallParams {
                    u_b: f64::INFINITY,
                    ..base
                },
            ),
            (
                "e_b",
                BallParams {
                    e_b: f64::NAN,
                    ..base
                },
            ),
            ("e_c", BallParams { e_c: -0.5, ..base }),
            ("f_c", BallParams { f_c: -0.5, ..base }),
            ("g", BallParams { g: 0.0, ..base }),
            (
                "g",
                BallParams {
                    g: f64::NAN,
                    ..base
                },
            ),
            (
                "mass",
                BallParams {
                    mass: f64::NAN,
                    ..base
                },
            ),
        ];
        for (name, params) in cases {
            assert_eq!(params.check().unwrap_err().argument(), name);
        }
        // Zero frictions are states that never end, not errors.
        let still = BallParams {
            u_s: 0.0,
            u_r: 0.0,
            u_sp_proportionality: 0.0,
            ..base
        };
        still.check().unwrap();
    }
}
