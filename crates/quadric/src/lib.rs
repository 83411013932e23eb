//! Ellipsoids as quadric matrices, the characteristic quartic det(λA+B) and the static classifier of Theorem 3.10
