//! The numbers the ray cast runs over: `f64` for the search and
//! outward-rounded [`Interval`]s for the proofs, with one set of formulas
//! ([`crate::support`]) for both.

use ccd_arith::{DwBall, Interval, Rat};
use std::ops::{Add, Mul, Neg, Sub};

/// A vector of ℝ³.
pub type V3<T> = [T; 3];
/// A 3×3 matrix, by rows.
pub type M3<T> = [[T; 3]; 3];

/// Field operations shared by `f64` (rounded, for the search) and
/// [`Interval`] (enclosures, for the proofs).
pub trait Scalar:
    Copy + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self> + Neg<Output = Self>
{
    /// The number `x` (a point interval).
    fn of(x: f64) -> Self;
    /// `self / d`.
    fn over(self, d: Self) -> Self;
    /// `√self` of a quantity known to be `>= 0`.
    fn root(self) -> Self;
    /// An enclosure of `x` (for `f64`: a value within an ulp of it).
    fn rat(x: &Rat) -> Self;
    /// An enclosure of the integer `x` (for `f64`: its rounding).
    fn int(x: i128) -> Self;
    /// Whether the value is finite (an enclosure that says something).
    fn known(self) -> bool;
    /// Whether the value is proven `> 0` (for `f64`: merely is).
    fn positive(self) -> bool;
}

impl Scalar for f64 {
    fn of(x: f64) -> f64 {
        x
    }
    fn over(self, d: f64) -> f64 {
        self / d
    }
    fn root(self) -> f64 {
        self.max(0.0).sqrt()
    }
    fn rat(x: &Rat) -> f64 {
        // Within an ulp of `x` (the search needs no more), and quicker than
        // `Rat::to_f64`'s correct rounding for short decimal numbers.
        Interval::from_rat(x).mid()
    }
    fn int(x: i128) -> f64 {
        Interval::from_i128(x).mid()
    }
    fn known(self) -> bool {
        self.is_finite()
    }
    fn positive(self) -> bool {
        self > 0.0
    }
}

impl Scalar for Interval {
    fn of(x: f64) -> Interval {
        Interval::point(x)
    }
    fn over(self, d: Interval) -> Interval {
        self / d
    }
    fn root(self) -> Interval {
        self.sqrt()
    }
    fn rat(x: &Rat) -> Interval {
        Interval::from_rat(x)
    }
    fn int(x: i128) -> Interval {
        Interval::from_i128(x)
    }
    fn known(self) -> bool {
        self.is_finite()
    }
    fn positive(self) -> bool {
        self.lo > 0.0
    }
}

/// Double words (about 106 bits) with a proven radius: the instant's
/// final enclosure.
impl Scalar for DwBall {
    fn of(x: f64) -> DwBall {
        DwBall::exact(x)
    }
    fn over(self, d: DwBall) -> DwBall {
        self.div(&d)
    }
    fn root(self) -> DwBall {
        self.sqrt()
    }
    fn rat(x: &Rat) -> DwBall {
        DwBall::from_rat(x)
    }
    fn int(x: i128) -> DwBall {
        DwBall::from_i128(x)
    }
    fn known(self) -> bool {
        self.is_known()
    }
    fn positive(self) -> bool {
        self.sign() == Some(1)
    }
}

/// `a·b`.
pub fn dot<T: Scalar>(a: &V3<T>, b: &V3<T>) -> T {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// `m·x`.
pub fn apply<T: Scalar>(m: &M3<T>, x: &V3<T>) -> V3<T> {
    std::array::from_fn(|i| dot(&m[i], x))
}

/// `a × b`.
pub fn cross<T: Scalar>(a: &V3<T>, b: &V3<T>) -> V3<T> {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// `a + s·b`.
pub fn axpy<T: Scalar>(a: &V3<T>, s: T, b: &V3<T>) -> V3<T> {
    std::array::from_fn(|i| a[i] + s * b[i])
}

/// `aᵀ·m·b`.
pub fn form<T: Scalar>(a: &V3<T>, m: &M3<T>, b: &V3<T>) -> T {
    dot(a, &apply(m, b))
}

/// Each entry of `x` as a point of `T`.
pub fn lift<T: Scalar>(x: &V3<f64>) -> V3<T> {
    x.map(T::of)
}

/// The symmetric matrix with entries `f(i, j)` for `i <= j` (six
/// evaluations).
pub fn symmetric<T: Copy>(f: impl Fn(usize, usize) -> T) -> M3<T> {
    let [a, b, c, d, e, g] = [(0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2)].map(|(i, j)| f(i, j));
    [[a, b, c], [b, d, e], [c, e, g]]
}
