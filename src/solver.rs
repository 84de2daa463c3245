//! The contact solve: small dense LU, Lemke's method, and the complementarity solver on the
//! condensed contact points; low-rank corrections that spare refactorisations when a few
//! points enter or leave contact (`capacitance` for the contact solve, `updated_lu` for the
//! steady state's Newton iterations).

pub mod capacitance;
pub mod complementarity;
pub mod dense;
pub mod fretting;
pub mod lemke;
pub mod partial_slip;
pub mod updated_lu;
