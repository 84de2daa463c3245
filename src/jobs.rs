//! The jobs the command line and the Python layer run: elastic, contact, run and steady (driver), parameter studies (sweep), and the validation report.

pub mod codes;
pub mod driver;
pub mod heat;
pub mod json;
pub mod p_check;
mod run;
pub mod steady_check;
pub mod sweep;
pub mod validate;
pub mod validity;
pub mod warnings;
