//! Inverse placements: the matrices `N` with `Xbody ∝ N·X` (homogeneous
//! coordinates, up to a positive scalar), for the rigid and affine kinds.
//! Generic over the ring, so one code path serves static bodies (rational
//! entries) and moving ones (entries polynomial in t).

use crate::matrix::{adj3, det3, Mat3, Mat4};
use ccd_arith::RingOps;

/// Hamilton product `p ⊗ q` (so that `R(p ⊗ q) = R(p)·R(q)`).
pub fn quat_mul<N: RingOps>(p: &[N; 4], q: &[N; 4]) -> [N; 4] {
    let [a1, b1, c1, d1] = p;
    let [a2, b2, c2, d2] = q;
    let m = |x: &N, y: &N| x.times(y);
    [
        m(a1, a2)
            .minus(&m(b1, b2))
            .minus(&m(c1, c2))
            .minus(&m(d1, d2)),
        m(a1, b2)
            .plus(&m(b1, a2))
            .plus(&m(c1, d2))
            .minus(&m(d1, c2)),
        m(a1, c2)
            .minus(&m(b1, d2))
            .plus(&m(c1, a2))
            .plus(&m(d1, b2)),
        m(a1, d2)
            .plus(&m(b1, c2))
            .minus(&m(c1, b2))
            .plus(&m(d1, a2)),
    ]
}

/// `M(q)`, the rotation numerator of the contract: `R(q) = M(q)/|q|²` for a
/// quaternion `q = [w, x, y, z]` (not necessarily unit).
pub fn rotation_numerator<R: RingOps>(q: &[R; 4]) -> Mat3<R> {
    let [w, x, y, z] = q;
    let sq = |a: &R| a.times(a);
    let (ww, xx, yy, zz) = (sq(w), sq(x), sq(y), sq(z));
    let two = R::from_i64(2);
    let tw = |a: &R, b: &R, c: &R, d: &R, plus: bool| {
        let s = a.times(b);
        let t = c.times(d);
        two.times(&if plus { s.plus(&t) } else { s.minus(&t) })
    };
    [
        [
            ww.plus(&xx).minus(&yy).minus(&zz),
            tw(x, y, w, z, false),
            tw(x, z, w, y, true),
        ],
        [
            tw(x, y, w, z, true),
            ww.minus(&xx).plus(&yy).minus(&zz),
            tw(y, z, w, x, false),
        ],
        [
            tw(x, z, w, y, false),
            tw(y, z, w, x, true),
            ww.minus(&xx).minus(&yy).plus(&zz),
        ],
    ]
}

/// `|q|² = w² + x² + y² + z²`.
pub fn norm2<R: RingOps>(q: &[R; 4]) -> R {
    q.iter().fold(R::zero(), |acc, c| acc.plus(&c.times(c)))
}

/// The homogeneous matrix `[[x, col], [0, corner]]`.
fn block<R: RingOps>(x: Mat3<R>, col: [R; 3], corner: R) -> Mat4<R> {
    // The entries are moved, not cloned.
    let [r0, r1, r2] = x;
    let [c0, c1, c2] = col;
    let row = |[a, b, c]: [R; 3], d: R| [a, b, c, d];
    [
        row(r0, c0),
        row(r1, c1),
        row(r2, c2),
        [R::zero(), R::zero(), R::zero(), corner],
    ]
}

/// `s·x` entrywise.
fn scaled<R: RingOps>(s: &R, x: &Mat3<R>) -> Mat3<R> {
    x.each_ref().map(|row| row.each_ref().map(|e| s.times(e)))
}

/// Inverse of the rigid placement `X = R·Xbody + C/w` with `R = M/n`
/// (`n = |q|² > 0`, `w > 0`): `[[Rᵀ, −Rᵀc], [0, 1]]` times the positive
/// factor `w·n`, i.e. `[[w·Mᵀ, −Mᵀ·C], [0, w·n]]`.
pub fn rigid_inverse<R: RingOps>(m: &Mat3<R>, n: &R, center: &[R; 3], w: &R) -> Mat4<R> {
    inverse_block(w, |i, j| &m[j][i], center, w.times(n))
}

/// `[[s·X, −X·v], [0, corner]]` with `X = (x(i, j))`, built where it is
/// returned: each entry is formed in its slot ([`RingOps::set_product`],
/// [`RingOps::add_product`]), the same operations as `s.times(x)` and a
/// dot product, but no intermediate matrix of large values (polynomial
/// entries) moved into place.
fn inverse_block<'a, R: RingOps + 'a>(
    s: &R,
    x: impl Fn(usize, usize) -> &'a R,
    v: &[R; 3],
    corner: R,
) -> Mat4<R> {
    let mut out: Mat4<R> = std::array::from_fn(|_| std::array::from_fn(|_| R::zero()));
    for (i, row) in out.iter_mut().take(3).enumerate() {
        for (j, e) in row.iter_mut().take(3).enumerate() {
            e.set_product(s, x(i, j));
        }
        let mut t = R::zero();
        for (k, vk) in v.iter().enumerate() {
            t.add_product(x(i, k), vk, false);
        }
        row[3] = t.negated();
    }
    out[3][3] = corner;
    out
}

/// The rigid placement `X = R·Xbody + C/w` with `R = M/n` itself, as a
/// homogeneous matrix times the factor `n·w` (nonzero): `[[w·M, n·C], [0, n·w]]`.
/// Its determinant is `n⁴·w⁴` (`det M = n³`).
pub fn rigid_placement<R: RingOps>(m: &Mat3<R>, n: &R, center: &[R; 3], w: &R) -> Mat4<R> {
    block(
        scaled(w, m),
        center.each_ref().map(|c| n.times(c)),
        n.times(w),
    )
}

/// The affine placement `X = (L·Xbody + d)/w` as the homogeneous matrix
/// `[[L, d], [0, w]]` (determinant `w·det L`).
pub fn affine_placement<R: RingOps>(l: &Mat3<R>, d: &[R; 3], w: &R) -> Mat4<R> {
    block(l.clone(), d.clone(), w.clone())
}

/// Inverse of the affine placement `X = (L·Xbody + d)/w` up to the nonzero
/// factor `w·det L` (whose square is what the quadric sees): the adjugate of
/// `[[L, d], [0, w]]`, which is `[[w·adj L, −adj(L)·d], [0, det L]]`.
pub fn affine_inverse<R: RingOps>(l: &Mat3<R>, d: &[R; 3], w: &R) -> Mat4<R> {
    let adj = adj3(l);
    inverse_block(w, |i, j| &adj[i][j], d, det3(l))
}

/// The body quadric `diag(1/r0², 1/r1², 1/r2², −1)` times the positive
/// factor `(r0·r1·r2)²`: `diag((r1r2)², (r0r2)², (r0r1)², −(r0r1r2)²)`.
/// Interior points satisfy `Xᵀ D X < 0`.
pub fn body_diagonal<R: RingOps>(radii: &[R; 3]) -> [R; 4] {
    let [r0, r1, r2] = radii;
    let sq = |a: &R| a.times(a);
    let all = r0.times(r1).times(r2);
    [
        sq(&r1.times(r2)),
        sq(&r0.times(r2)),
        sq(&r0.times(r1)),
        sq(&all).negated(),
    ]
}
