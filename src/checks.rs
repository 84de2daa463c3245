//! The model-validity checks a result is judged by: the warnings on the contact, the mesh and
//! the model's assumptions (warnings, validity), the check in p (p_check), the run against
//! its steady state (steady_check), and the warning codes (codes). They read the problem and
//! the stages' results, and know nothing of the jobs that call them.

pub mod codes;
pub mod edge_fit;
pub mod p_check;
pub mod steady_check;
pub mod validity;
pub mod warnings;
