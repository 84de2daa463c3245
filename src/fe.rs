//! The finite element model: quadrature, shape functions, exact geometry, mesh, materials, dof numbering, elasticity with condensation and factorisation, loads and post-processing.

pub mod basis;
pub mod conduction;
pub mod dofs;
pub mod elasticity;
pub mod fields;
pub mod geometry;
pub mod loads;
pub mod material;
pub mod mesh;
pub mod quadrature;
