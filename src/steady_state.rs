//! Steady worn states without time integration: the exact semismooth Newton solve, and the paper's §6 methods (monotonic and averaged shapes, spline and penalty iterations), and the steady state with heat.

pub mod monotonic_shape;
pub mod paper_steady;
pub mod spline_method;
pub mod steady;
pub mod thermal;
