//! Extreme radius ratios up to `10⁴⁰⁹⁶`: a needle `(1, 10⁻ᵏ, 10⁻ᵏ)` along
//! `x` or a disc `(1, 1, 10⁻ᵏ)`, turned about the vertical, with the
//! ellipsoid `B = (1, 1/2, 3/4)` passing over it at a known distance — the
//! non-homothetic graze of [`super::graze`], whose truth holds for any
//! semi-axes: `A`'s top point is at height 0 with a horizontal tangent
//! plane (its centre at `−10⁻ᵏ`), `B`'s bottom point passes over it at
//! height `g ∈ {+1/8, 0, −1/8}`. So: separate throughout; one touch at
//! `u* = 3/7`; two contacts, bracketed by the tangent balls (for the needle,
//! the outer ball has radius `10ᵏ`, so the bracket reaches the span's end
//! and only the side of `u*` is known).

use super::graze::{about_z, Graze};
use super::{int, pow10, rat, v3};
use crate::{Case, Level, StabilityError};
use ccd_arith::Rat;
use ccd_motion::Vec3;

/// The exponents: `10⁻¹ … 10⁻⁴⁰⁹⁶` by doubling.
fn ratio_ks(level: Level) -> Vec<u32> {
    match level {
        Level::Shipped => vec![1, 64],
        Level::Full => (0..=12).map(|i| 1 << i).collect(),
    }
}

/// The three gaps of every `k`, for `A` with semi-axes `a(k)`.
fn extreme(
    family: &str,
    level: Level,
    a: impl Fn(Rat) -> Vec3,
) -> Result<Vec<Case>, StabilityError> {
    let mut out = Vec::new();
    for k in ratio_ks(level) {
        let g = Graze {
            a_turn: about_z(int(2), int(1)),
            ..Graze::new(a(pow10(-(k as i32))), v3(int(1), rat(1, 2), rat(3, 4)))
        };
        for (tag, gap) in [
            ("miss", rat(1, 8)),
            ("touch", Rat::zero()),
            ("overlap", rat(-1, 8)),
        ] {
            out.push(g.pass(family, format!("k{k:04}-{tag}"), Some(k), gap)?);
        }
    }
    Ok(out)
}

/// A needle `(1, 10⁻ᵏ, 10⁻ᵏ)`.
pub fn ratio_needle(level: Level) -> Result<Vec<Case>, StabilityError> {
    extreme("ratio-needle", level, |e| v3(int(1), e.clone(), e))
}

/// A disc `(1, 1, 10⁻ᵏ)`.
pub fn ratio_disc(level: Level) -> Result<Vec<Case>, StabilityError> {
    extreme("ratio-disc", level, |e| v3(int(1), int(1), e))
}
