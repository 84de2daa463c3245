//! Warning codes. Every warning is one line, `warning[CODE]: FILE: what`; the explanation of
//! each code is its section of docs/warnings.md, compiled in, which `wearfem explain CODE`
//! prints.

/// docs/warnings.md, whose `## CODE` sections explain the codes.
pub const WARNINGS_MD: &str = include_str!("../../docs/warnings.md");

/// The warning line for `code` about problem file `file`: `warning[CODE]: FILE: text`.
pub fn warning(code: &str, file: &str, text: impl std::fmt::Display) -> String {
    debug_assert!(
        explain(code).is_some(),
        "warning code {code} is not in docs/warnings.md"
    );
    format!("warning[{code}]: {file}: {text}")
}

/// Every code docs/warnings.md explains, in its order.
pub fn codes() -> Vec<&'static str> {
    WARNINGS_MD
        .lines()
        .filter_map(|l| l.strip_prefix("## "))
        .map(str::trim)
        .collect()
}

/// The explanation of `code` (its section of docs/warnings.md without the heading); None
/// for a code that does not exist.
pub fn explain(code: &str) -> Option<String> {
    let mut lines = WARNINGS_MD.lines();
    lines.find(|l| l.strip_prefix("## ").map(str::trim) == Some(code))?;
    let text: Vec<&str> = lines.take_while(|l| !l.starts_with("## ")).collect();
    Some(text.join("\n").trim().to_string())
}

/// The code of a warning line (`warning[CODE]: …`), if it has one.
pub fn code_of(line: &str) -> Option<&str> {
    line.strip_prefix("warning[")?.split(']').next()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_code_has_an_explanation_and_lines_carry_their_code() {
        let codes = codes();
        assert!(codes.len() > 30, "{codes:?}");
        for code in &codes {
            let text = explain(code).unwrap();
            assert!(text.len() > 40, "{code}: {text}");
            assert!(!code.contains(' '), "a code is one word: {code}");
        }
        let line = warning("p-check", "a.toml", "not converged");
        assert_eq!(line, "warning[p-check]: a.toml: not converged");
        assert_eq!(code_of(&line), Some("p-check"));
        assert!(explain("no-such-code").is_none());
    }
}
