//! Univariate polynomials in t with exact big-integer and rational coefficients, in power and Bernstein form
