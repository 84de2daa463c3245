//! The jobs the command line and the Python layer run: elastic, contact, run and steady (driver), parameter studies (sweep), and the validation report.

pub mod driver;
pub mod fretting;
pub mod heat;
mod run;
pub mod sliding;
pub mod sliding_steady;
pub mod sweep;
pub mod validate;
