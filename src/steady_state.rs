//! Steady worn states without time integration: the exact semismooth Newton solve, and the paper's §6 methods (monotonic and averaged shapes, spline and penalty iterations), and the steady state with heat, and the steady state of sliding pairs (where one exists), and the final state of fretting in partial slip.

pub mod fretting;
pub mod monotonic_shape;
pub mod paper_steady;
pub mod sliding;
pub mod spline_method;
pub mod steady;
pub mod thermal;
