//! Output: JSON, CSV, figures (plot), ParaView files (vtk) and the deformed bodies behind a contact solve that they draw.

pub mod deformation;
pub mod fretting;
pub mod json;
pub mod output;
pub mod plot;
pub mod sliding;
pub mod vtk;
