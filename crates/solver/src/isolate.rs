//! Real root isolation by Bernstein subdivision and Descartes' rule of signs.
//!
//! For a squarefree polynomial `p` of degree `n` with Bernstein coefficients
//! `b_0..b_n` over `[lo, hi]`, the number of roots in the open interval is
//! `Var(b) − 2k` for some `k >= 0` (Descartes' rule in Bernstein form), so
//! `Var(b) = 0` proves there is none and `Var(b) = 1` proves there is exactly
//! one. Otherwise the interval is halved by de Casteljau's algorithm. For a
//! squarefree `p` this terminates (the "two-circle" theorem).
//!
//! Roots come out lazily and in increasing order (depth-first, left half
//! first), so a caller that wants only the earliest root isolates no other.
//!
//! Every node first tries the `f64`-interval filter; a node with a
//! coefficient whose sign the filter cannot prove is recomputed in exact
//! integers, and stays exact while its signs need it.

use crate::float_bernstein::FloatBernstein;
use crate::root::{RealRoot, SignProbe};
use ccd_arith::Rat;
use ccd_poly::{Bernstein, ZPoly};
use std::sync::Arc;

enum Coeffs {
    Float(FloatBernstein),
    Exact(Bernstein),
}

struct Node {
    lo: Rat,
    hi: Rat,
    coeffs: Coeffs,
}

enum Item {
    Root(RealRoot),
    Node(Node),
}

/// Sign variations of a sign sequence, zeros skipped.
fn variations(signs: &[i32]) -> usize {
    let mut last = 0;
    let mut v = 0;
    for &s in signs {
        if s != 0 {
            if last != 0 && s != last {
                v += 1;
            }
            last = s;
        }
    }
    v
}

impl Node {
    fn exact(p: &ZPoly, lo: Rat, hi: Rat) -> Node {
        let b = Bernstein::from_power(p, &lo, &hi);
        Node {
            lo,
            hi,
            coeffs: Coeffs::Exact(b),
        }
    }

    /// Prefers the float form of exact coefficients whenever the filter can
    /// sign every coefficient.
    fn from_exact_bernstein(b: Bernstein) -> Node {
        let (lo, hi) = (b.lo().clone(), b.hi().clone());
        let f = FloatBernstein::from_exact(b.coeffs(), b.scale().signum());
        let coeffs = if f.signs().is_some() {
            Coeffs::Float(f)
        } else {
            Coeffs::Exact(b)
        };
        Node { lo, hi, coeffs }
    }

    fn signs(&self) -> Option<Vec<i32>> {
        match &self.coeffs {
            Coeffs::Float(f) => f.signs(),
            Coeffs::Exact(b) => {
                let s = b.scale().signum();
                Some(b.coeffs().iter().map(|c| c.signum() * s).collect())
            }
        }
    }

    /// Halves the node; returns the children and the sign of `p` at the
    /// split point when the coefficients prove it.
    fn split(self) -> (Node, Node, Option<i32>) {
        let mid = Rat::midpoint(&self.lo, &self.hi);
        match self.coeffs {
            Coeffs::Float(f) => {
                let (l, r) = f.split_half();
                let s = l.sign_at_hi();
                let left = Node {
                    lo: self.lo,
                    hi: mid.clone(),
                    coeffs: Coeffs::Float(l),
                };
                let right = Node {
                    lo: mid,
                    hi: self.hi,
                    coeffs: Coeffs::Float(r),
                };
                (left, right, s)
            }
            Coeffs::Exact(b) => {
                let (l, r) = b.split_half();
                let s = l.sign_at_hi();
                (
                    Node::from_exact_bernstein(l),
                    Node::from_exact_bernstein(r),
                    Some(s),
                )
            }
        }
    }

    /// Marks the shared endpoint as an exact root in the float form.
    fn set_endpoint_zero(&mut self, at_hi: bool) {
        if let Coeffs::Float(f) = &mut self.coeffs {
            f.set_end_zero(at_hi);
        }
    }
}

/// The real roots of a squarefree polynomial in a closed interval, isolated
/// lazily in increasing order. Built by [`crate::isolate`].
pub struct RootIter {
    base: Arc<SignProbe>,
    stack: Vec<Item>,
}

impl RootIter {
    /// `p` must be squarefree, nonzero and of degree >= 1; `lo < hi`.
    pub(crate) fn new(base: Arc<SignProbe>, lo: &Rat, hi: &Rat) -> RootIter {
        let poly = base.poly();
        let (first, last) = (poly.sign_at(lo), poly.sign_at(hi));
        let mut stack = Vec::new();
        if last == 0 {
            stack.push(Item::Root(RealRoot::exact(base.clone(), hi.clone())));
        }
        // The filter straight from the power basis when the ends are not
        // roots; the exact conversion otherwise (or if it cannot sign).
        let float = (first != 0 && last != 0)
            .then(|| FloatBernstein::from_power(poly, lo, hi))
            .flatten();
        let root = match float {
            Some(f) => Node {
                lo: lo.clone(),
                hi: hi.clone(),
                coeffs: Coeffs::Float(f),
            },
            None => Node::from_exact_bernstein(Bernstein::from_power(poly, lo, hi)),
        };
        stack.push(Item::Node(root));
        if first == 0 {
            stack.push(Item::Root(RealRoot::exact(base.clone(), lo.clone())));
        }
        RootIter { base, stack }
    }
}

impl Iterator for RootIter {
    type Item = RealRoot;

    fn next(&mut self) -> Option<RealRoot> {
        while let Some(item) = self.stack.pop() {
            let node = match item {
                Item::Root(r) => return Some(r),
                Item::Node(n) => n,
            };
            let Some(signs) = node.signs() else {
                // The filter cannot sign a coefficient: redo this node exactly.
                self.stack
                    .push(Item::Node(Node::exact(self.base.poly(), node.lo, node.hi)));
                continue;
            };
            let var = variations(&signs);
            if var == 0 {
                continue;
            }
            let (first, last) = (signs[0], signs[signs.len() - 1]);
            if var == 1 && first != 0 && last != 0 {
                return Some(RealRoot::isolated(
                    self.base.clone(),
                    node.lo,
                    node.hi,
                    first,
                ));
            }
            let mid = Rat::midpoint(&node.lo, &node.hi);
            let (mut left, mut right, mid_sign) = node.split();
            let mid_sign = mid_sign.unwrap_or_else(|| self.base.poly().sign_at(&mid));
            if mid_sign == 0 {
                right.set_endpoint_zero(false);
            }
            self.stack.push(Item::Node(right));
            if mid_sign == 0 {
                left.set_endpoint_zero(true);
                self.stack
                    .push(Item::Root(RealRoot::exact(self.base.clone(), mid)));
            }
            self.stack.push(Item::Node(left));
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::variations;

    #[test]
    fn variations_skip_zeros() {
        assert_eq!(variations(&[1, 0, -1, 0, 0, 1]), 2);
        assert_eq!(variations(&[0, 0]), 0);
        assert_eq!(variations(&[-1, -1, 1]), 1);
    }
}
