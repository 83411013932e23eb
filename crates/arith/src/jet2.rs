//! [`Jet2`]: second-order jets `(f, f′, f″)` over any [`RingOps`], the
//! flat form of the nested dual numbers `Dual<Dual<T>>` (whose `v.d` and
//! `d.v` both carry `f′`).
//!
//! A product of jets is Leibniz's rule,
//!
//! ```text
//! (fg)′ = f·g′ + f′·g,    (fg)″ = (f·g″ + f′·g′) + (f′·g′ + f″·g),
//! ```
//!
//! grouped exactly as the nested product groups it (the two inner
//! products of the outer derivative), so `f′·g′` is formed once: 6 ring
//! products where the nested type forms 9. The nested type's shortcuts
//! for exactly zero derivatives are kept too, term for term.
//!
//! Bitwise equality with the nested type holds when its two copies of
//! `f′` stay equal. They do where every jet with `f′ = 0` (exactly,
//! [`RingOps::is_zero`]) also has `f″ = 0`, and over [`crate::Interval`]
//! for every jet: its ring operations make a product with the exact zero
//! the exact zero and a sum with it the other operand, bit for bit, so
//! each shortcut gives the very term it skips. Over exact rings the two
//! types agree in value always.

use crate::RingOps;

/// The jet `(v, d, dd)` of a function: its value and first and second
/// derivatives (over intervals: enclosures of them over a box).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Jet2<T> {
    /// Value `f`.
    pub v: T,
    /// First derivative `f′`.
    pub d: T,
    /// Second derivative `f″`.
    pub dd: T,
}

impl<T: RingOps> Jet2<T> {
    /// A constant (both derivatives 0).
    pub fn constant_of(v: T) -> Jet2<T> {
        Jet2 {
            v,
            d: T::zero(),
            dd: T::zero(),
        }
    }
    /// `(f′, f″)` are both exactly zero: the nested type's test of its
    /// outer derivative.
    fn is_constant(&self) -> bool {
        self.d.is_zero() && self.dd.is_zero()
    }
    /// The nested inner product's derivative `a·e + b·c` of `(a, b)·(c, e)`
    /// with its shortcuts: `a·e` alone when `b = 0`, `b·c` alone when
    /// `e = 0` (the products given as `ae`, `bc`).
    fn inner(b: &T, e: &T, ae: impl FnOnce() -> T, bc: impl FnOnce() -> T) -> T {
        if b.is_zero() {
            ae()
        } else if e.is_zero() {
            bc()
        } else {
            ae().plus(&bc())
        }
    }
}

impl<T: RingOps> RingOps for Jet2<T> {
    fn zero() -> Self {
        Jet2::constant_of(T::zero())
    }
    fn one() -> Self {
        Jet2::constant_of(T::one())
    }
    fn from_i64(v: i64) -> Self {
        Jet2::constant_of(T::from_i64(v))
    }
    fn is_zero(&self) -> bool {
        self.v.is_zero() && self.d.is_zero() && self.dd.is_zero()
    }
    fn plus(&self, o: &Self) -> Self {
        Jet2 {
            v: self.v.plus(&o.v),
            d: self.d.plus(&o.d),
            dd: self.dd.plus(&o.dd),
        }
    }
    fn minus(&self, o: &Self) -> Self {
        Jet2 {
            v: self.v.minus(&o.v),
            d: self.d.minus(&o.d),
            dd: self.dd.minus(&o.dd),
        }
    }
    /// Leibniz's rule as the nested product forms it: for `f = self`,
    /// `g = o`, outer derivative `(f, f′)·(g′, g″) + (f′, f″)·(g, g′)`
    /// (only the first term when `f` is constant, only the second when
    /// `g` is), each inner product `a·e + b·c` with its own shortcuts.
    fn times(&self, o: &Self) -> Self {
        let (f, fd, fdd) = (&self.v, &self.d, &self.dd);
        let (g, gd, gdd) = (&o.v, &o.d, &o.dd);
        let (d, dd) = if self.is_constant() {
            // (f, 0)·(g′, g″).
            (f.times(gd), f.times(gdd))
        } else if o.is_constant() {
            // (f′, f″)·(g, 0).
            let dd = if fdd.is_zero() {
                fd.times(gd)
            } else {
                fdd.times(g)
            };
            (fd.times(g), dd)
        } else {
            // f′·g′ is both inner products' `b·c` resp. `a·e`: formed once.
            let fd_gd = fd.times(gd);
            let p = Jet2::inner(fd, gdd, || f.times(gdd), || fd_gd.clone());
            let q = Jet2::inner(fdd, gd, || fd_gd.clone(), || fdd.times(g));
            (f.times(gd).plus(&fd.times(g)), p.plus(&q))
        };
        Jet2 {
            v: f.times(g),
            d,
            dd,
        }
    }
    fn negated(&self) -> Self {
        Jet2 {
            v: self.v.negated(),
            d: self.d.negated(),
            dd: self.dd.negated(),
        }
    }
    fn div_small(&self, k: i64) -> Self {
        Jet2 {
            v: self.v.div_small(k),
            d: self.d.div_small(k),
            dd: self.dd.div_small(k),
        }
    }
}
