//! [`sign_variations`]: the sign changes Descartes' rule of signs counts.

/// The number of sign changes in a sequence of signs (any negative value
/// counts as −, any positive as +), zeros skipped: Descartes' rule of
/// signs (the paper's Proposition 3.1) on power or Bernstein coefficients.
///
/// ```
/// use ccd_arith::sign_variations;
/// assert_eq!(sign_variations([1, -1, 0, 1, 1]), 2);
/// assert_eq!(sign_variations([0, 0, 0]), 0);
/// ```
pub fn sign_variations(signs: impl IntoIterator<Item = i32>) -> usize {
    let mut nonzero = signs.into_iter().filter(|s| *s != 0).map(i32::signum);
    let Some(mut last) = nonzero.next() else {
        return 0;
    };
    let mut count = 0;
    for s in nonzero {
        if s != last {
            count += 1;
            last = s;
        }
    }
    count
}
