//! The `gmp` feature: dashu's kernel ([`backend_dashu`](crate::backend_dashu))
//! for every number, with the operations whose cost grows faster than
//! linearly handed to GMP (through rug) once both operands are long.
//!
//! GMP on its own was measured slower than dashu on this project's short
//! numbers (+26 % to +88 % instructions on the benchmark scenes: every
//! result is a heap buffer, where dashu keeps up to two words inline) and
//! faster on long ones (−42 % on a scene of 12,000-bit polynomials, its
//! products and gcds being asymptotically faster). So the choice is made
//! per operation and size: a product, a gcd or a division whose operands
//! both have at least [`LONG_WORDS`] words converts them (one copy each
//! way, linear) and runs in GMP; everything else stays in dashu. The
//! values are the same whichever kernel computes them.

use dashu_int::{IBig, Sign};
use rug::integer::Order;
use rug::{Complete, Integer};

/// Operands of at least this many 64-bit words (both) go to GMP: below it
/// the two conversions cost more than GMP saves (measured with
/// `benches/instructions.sh`, docs/table4.md).
pub(crate) const LONG_WORDS: usize = 16;

/// Whether both operands are long enough for GMP: the one test on every
/// operation's path (inlined; the GMP calls themselves are not).
#[inline(always)]
pub(crate) fn both_long(a: &IBig, b: &IBig) -> bool {
    a.as_sign_words().1.len() >= LONG_WORDS && b.as_sign_words().1.len() >= LONG_WORDS
}

fn to_gmp(a: &IBig) -> Integer {
    let (s, w) = a.as_sign_words();
    let m = Integer::from_digits(w, Order::Lsf);
    if s == Sign::Negative {
        -m
    } else {
        m
    }
}

fn to_dashu(x: &Integer) -> IBig {
    let s = if x.is_negative() {
        Sign::Negative
    } else {
        Sign::Positive
    };
    IBig::from_sign_words(s, x.as_limbs())
}

/// `a·b` by GMP ([`both_long`] operands).
#[cold]
#[inline(never)]
pub(crate) fn mul(a: &IBig, b: &IBig) -> IBig {
    to_dashu(&(&to_gmp(a) * &to_gmp(b)).complete())
}

/// `gcd(|a|, |b|)` by GMP ([`both_long`] operands).
#[cold]
#[inline(never)]
pub(crate) fn gcd(a: &IBig, b: &IBig) -> IBig {
    to_dashu(&to_gmp(a).gcd_ref(&to_gmp(b)).complete())
}

/// Truncated quotient and remainder by GMP ([`both_long`] operands).
#[cold]
#[inline(never)]
pub(crate) fn div_rem_trunc(a: &IBig, b: &IBig) -> (IBig, IBig) {
    let (q, r) = to_gmp(a).div_rem_ref(&to_gmp(b)).complete();
    (to_dashu(&q), to_dashu(&r))
}

#[cfg(test)]
mod tests {
    use super::*;
    use dashu_int::ops::{DivRem, Gcd};
    use proptest::prelude::*;

    /// Signed integers of `len` random words, so that both kernels' long
    /// paths (and the conversions, signs included) are exercised.
    fn long_int(words: std::ops::Range<usize>) -> impl Strategy<Value = IBig> {
        (
            proptest::collection::vec(any::<u64>(), words),
            any::<bool>(),
        )
            .prop_map(|(w, neg)| {
                let s = if neg { Sign::Negative } else { Sign::Positive };
                IBig::from_sign_words(s, &w)
            })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]
        /// GMP's product, gcd and truncated division of long operands are
        /// dashu's own (its operators, which these hooks bypass).
        #[test]
        fn gmp_agrees_with_dashu_on_long_operands(
            a in long_int(LONG_WORDS..3 * LONG_WORDS),
            b in long_int(LONG_WORDS..2 * LONG_WORDS),
            c in long_int(1..LONG_WORDS),
        ) {
            prop_assume!(both_long(&a, &b));
            prop_assert_eq!(mul(&a, &b), &a * &b);
            prop_assert_eq!(gcd(&a, &b), IBig::from((&a).gcd(&b)));
            // A common factor, so that the gcd is not 1.
            let (ac, bc) = (&a * &c, &b * &c);
            prop_assert_eq!(gcd(&ac, &bc), IBig::from((&ac).gcd(&bc)));
            prop_assert_eq!(div_rem_trunc(&a, &b), (&a).div_rem(&b));
            prop_assert_eq!(div_rem_trunc(&ac, &b), (&ac).div_rem(&b));
        }
    }
}
