//! Where numbers enter: exact conversions from `num-rational`'s
//! `BigRational`, from machine integers and from `f64` (its exact binary
//! value, never a rounded decimal).

use crate::{Int, Rat};
use num_rational::BigRational;

/// An `f64` that is not finite has no rational value.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
#[error("not a finite number")]
pub struct NotFinite;

impl From<&BigRational> for Rat {
    /// The same rational (the denominator of a `BigRational` is nonzero).
    fn from(x: &BigRational) -> Rat {
        // Through decimal text: `num-rational` 0.4 is built on another
        // `num-bigint` than the integer kernel.
        let int = |v: String| Int::parse_decimal(&v).expect("a decimal integer");
        Rat::new(int(x.numer().to_string()), int(x.denom().to_string()))
            .expect("a nonzero denominator")
    }
}

impl From<BigRational> for Rat {
    fn from(x: BigRational) -> Rat {
        Rat::from(&x)
    }
}

impl From<&Rat> for BigRational {
    /// The same rational.
    fn from(x: &Rat) -> BigRational {
        format!("{}/{}", x.numer(), x.denom())
            .parse()
            .expect("a fraction of decimal integers")
    }
}

impl TryFrom<f64> for Rat {
    type Error = NotFinite;
    /// The exact binary value of `x`: `0.1` is
    /// `3602879701896397/36028797018963968`, not `1/10`.
    fn try_from(x: f64) -> Result<Rat, NotFinite> {
        Rat::from_f64_exact(x).ok_or(NotFinite)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        /// BigRational → Rat → BigRational is the identity, and the value
        /// is kept (compared through f64 and exactly through strings).
        #[test]
        fn big_rational_round_trips(n in any::<i64>(), d in 1i64..i64::MAX, k in 0usize..200) {
            let x: BigRational = format!("{n}{}/{d}", "7".repeat(k)).parse().expect("a fraction");
            let r = Rat::from(&x);
            prop_assert_eq!(BigRational::from(&r), x.clone());
            prop_assert_eq!(r.to_string(), x.to_string());
        }

        /// An f64 is taken at its exact binary value.
        #[test]
        fn floats_are_exact(
            x in any::<f64>().prop_filter("finite", |x| x.is_finite()),
            k in -1022i32..-1000,
        ) {
            // The bottom of the normal range, where a clamped scale lost bits.
            let low = 1.5f64 * 2f64.powi(k);
            prop_assert_eq!(Rat::try_from(low).expect("finite").to_f64(), low);
            let r = Rat::try_from(x).expect("finite");
            // `to_f64` is exact on the normal range (53 bits from a 60-bit
            // quotient, then a power of two).
            if x == 0.0 || x.abs() >= f64::MIN_POSITIVE {
                prop_assert_eq!(r.to_f64(), x);
            }
            let d = r.denom();
            prop_assert_eq!(d.trailing_zeros().map_or(0, |z| z + 1), d.bits());
        }
    }

    #[test]
    fn a_decimal_float_is_not_its_decimal() {
        let tenth = Rat::try_from(0.1).expect("finite");
        assert_ne!(tenth, Rat::from_frac(1, 10));
        assert_eq!(tenth, Rat::from_frac(3602879701896397, 36028797018963968));
        assert_eq!(Rat::try_from(f64::NAN), Err(NotFinite));
    }
}
