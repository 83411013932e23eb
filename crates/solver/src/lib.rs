//! Exact real root isolation by Bernstein subdivision and Descartes' rule of signs, with certified refinement and sign decisions
