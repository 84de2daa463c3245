//! Problem input: the file schema, validation and model building, `--set` overrides, engineering wear units, and the built-in examples.

pub mod duration;
pub mod examples;
pub mod fretting;
pub mod gmsh;
pub mod heat;
pub mod overrides;
pub mod problem;
pub mod schema;
pub mod wear_units;
