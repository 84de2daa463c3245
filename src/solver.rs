//! The contact solve: small dense LU, Lemke's method, and the complementarity solver on the condensed contact points.

pub mod capacitance;
pub mod complementarity;
pub mod dense;
pub mod lemke;
pub mod updated_lu;
