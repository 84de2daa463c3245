//! The contact solve's settings from `[contact]`: the solver method and the first sliding
//! direction, as the solver stage takes them.

use super::{Problem, ProblemError};
use crate::complementarity::{Direction, Method};

impl Problem {
    /// The solver method named in the problem's `[contact]` section.
    pub fn contact_method(&self) -> Result<Method, ProblemError> {
        let problem = self;
        let c = problem
            .spec
            .contact
            .as_ref()
            .ok_or_else(|| problem.error("contact", "this problem has no [contact] section"))?;
        match c.method.as_str() {
            "active_set" => Ok(Method::ActiveSet),
            "lemke" => Ok(Method::Lemke),
            "penalty" => match c.penalty {
                Some(k) if k.is_finite() && k > 0.0 => Ok(Method::Penalty { stiffness: k }),
                other => Err(problem.error(
                    "contact.penalty",
                    match other {
                        Some(k) => {
                            format!("method \"penalty\" needs penalty > 0 (MPa/mm), got {k}")
                        }
                        None => {
                            "method \"penalty\" needs penalty > 0 (MPa/mm), which is missing".into()
                        }
                    },
                )),
            },
            other => Err(problem.error(
                "contact.method",
                format!("must be \"active_set\", \"lemke\" or \"penalty\", got \"{other}\""),
            )),
        }
    }

    /// The first sliding direction named in the problem.
    pub fn first_direction(&self) -> Result<Direction, ProblemError> {
        let problem = self;
        let c = problem
            .spec
            .contact
            .as_ref()
            .ok_or_else(|| problem.error("contact", "this problem has no [contact] section"))?;
        match c.direction.as_str() {
            "+" => Ok(Direction::Plus),
            "-" | "−" => Ok(Direction::Minus),
            other => Err(problem.error(
                "contact.direction",
                format!("must be \"+\" or \"-\", got \"{other}\""),
            )),
        }
    }
}
