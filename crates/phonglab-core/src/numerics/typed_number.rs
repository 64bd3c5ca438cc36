//! Numbers as students type them: a decimal point or a decimal comma (`0.5`, `0,5`,
//! `1,5e-3`), and vectors separated by spaces, commas or semicolons (`0.5, 0.3, 0.1`,
//! `0,5; 0,3; 0,1`, `[0,5 0,3 0,1]`). Nothing is truncated in silence: a number that is
//! not finite, lies outside single precision's range (±3.4e38), or is not zero but rounds
//! to zero in single precision (`1e-400`, `1e-50`) is refused, saying which.

use thiserror::Error;

/// Why a typed number was refused.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum TypedNumberError {
    /// Nothing was typed.
    #[error("{}", crate::t!("typed-empty"))]
    Empty,
    /// Not a number at all.
    #[error("{}", crate::t!("typed-not-a-number", text = .0))]
    NotANumber(String),
    /// NaN or infinity.
    #[error("{}", crate::t!("typed-not-finite", text = .0))]
    NotFinite(String),
    /// Beyond what a float holds.
    #[error("{}", crate::t!("typed-too-large", text = .0))]
    TooLarge(String),
    /// Not zero, but a float would hold it as zero.
    #[error("{}", crate::t!("typed-too-small", text = .0))]
    TooSmall(String),
}

/// Does the text of a number have a non-zero digit in its significand?
fn names_non_zero(text: &str) -> bool {
    let significand = text.split(['e', 'E']).next().unwrap_or("");
    significand.chars().any(|c| c.is_ascii_digit() && c != '0')
}

/// `text` (trimmed) with its decimal comma, when it has one (one comma and no point), as a
/// decimal point: the one rule for what a decimal comma is.
pub fn with_decimal_point(text: &str) -> String {
    let t = text.trim();
    if t.matches(',').count() == 1 && !t.contains('.') { t.replacen(',', ".", 1) } else { t.to_string() }
}

/// One number, with `.` or `,` as its decimal separator (one of them, once).
pub fn parse_number(text: &str) -> Result<f64, TypedNumberError> {
    let t = text.trim();
    if t.is_empty() {
        return Err(TypedNumberError::Empty);
    }
    let normalised = with_decimal_point(t);
    let lower = normalised.to_ascii_lowercase();
    if ["nan", "+nan", "-nan", "inf", "+inf", "-inf", "infinity", "+infinity", "-infinity"].contains(&lower.as_str()) {
        return Err(TypedNumberError::NotFinite(t.to_string()));
    }
    let x: f64 = normalised.parse().map_err(|_| TypedNumberError::NotANumber(t.to_string()))?;
    if !x.is_finite() || x.abs() > f32::MAX as f64 {
        return Err(TypedNumberError::TooLarge(t.to_string()));
    }
    if (x as f32) == 0.0 && names_non_zero(&normalised) {
        return Err(TypedNumberError::TooSmall(t.to_string()));
    }
    Ok(x)
}

/// Several numbers (a vector, a colour): separated by spaces, semicolons or commas, with
/// optional brackets. A part with one comma and no point is a number with a decimal comma
/// (`0,5 0,3` is two numbers, as `0,5; 0,3` is); otherwise commas separate (`0.5, 0.3`,
/// `1,2,3`).
pub fn parse_numbers(text: &str) -> Result<Vec<f64>, TypedNumberError> {
    let t = text.trim().trim_start_matches(['[', '(']).trim_end_matches([']', ')']);
    let mut out = Vec::new();
    for part in t.split(|c: char| c == ';' || c.is_whitespace()).filter(|s| !s.is_empty()) {
        let part = part.trim_end_matches(',');
        if part.is_empty() {
            continue;
        }
        if part.matches(',').count() == 1 && !part.contains('.') {
            out.push(parse_number(part)?);
        } else {
            for p in part.split(',').filter(|s| !s.is_empty()) {
                out.push(parse_number(p)?);
            }
        }
    }
    if out.is_empty() { Err(TypedNumberError::Empty) } else { Ok(out) }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_decimal_comma_reads_as_a_decimal_point() {
        assert_eq!(parse_number("12,5"), Ok(12.5));
        assert_eq!(parse_number("0,7246526"), Ok(0.7246526));
        assert_eq!(parse_number("1,5e-3"), Ok(1.5e-3));
        assert_eq!(parse_number(" -0.25 "), Ok(-0.25));
        assert_eq!(parse_number("1e38"), Ok(1e38));
        assert_eq!(parse_number("0"), Ok(0.0));
        assert_eq!(parse_number("0e-400"), Ok(0.0), "zero written small is zero");
    }

    #[test]
    fn nothing_is_truncated_in_silence() {
        assert_eq!(parse_number("1e400"), Err(TypedNumberError::TooLarge("1e400".into())));
        assert_eq!(parse_number("1e39"), Err(TypedNumberError::TooLarge("1e39".into())));
        assert_eq!(parse_number("1e-400"), Err(TypedNumberError::TooSmall("1e-400".into())));
        assert_eq!(parse_number("1e-50"), Err(TypedNumberError::TooSmall("1e-50".into())));
        assert!(parse_number("1e-40").is_ok(), "a subnormal float still holds it");
        assert_eq!(parse_number("NaN"), Err(TypedNumberError::NotFinite("NaN".into())));
        assert_eq!(parse_number("abc"), Err(TypedNumberError::NotANumber("abc".into())));
        assert_eq!(parse_number("1,2,3"), Err(TypedNumberError::NotANumber("1,2,3".into())));
        assert_eq!(parse_number(""), Err(TypedNumberError::Empty));
        assert!(parse_number("1e400").unwrap_err().to_string().contains("single precision"));
    }

    #[test]
    fn vectors_take_points_commas_and_semicolons() {
        assert_eq!(parse_numbers("0.5, 0.3, 0.1"), Ok(vec![0.5, 0.3, 0.1]));
        assert_eq!(parse_numbers("0,5; 0,3; 0,1"), Ok(vec![0.5, 0.3, 0.1]));
        assert_eq!(parse_numbers("[0,5 0,3 0,1 1]"), Ok(vec![0.5, 0.3, 0.1, 1.0]));
        assert_eq!(parse_numbers("1,2,3"), Ok(vec![1.0, 2.0, 3.0]));
        assert_eq!(parse_numbers("[0.79 0.56 -0.25 0]"), Ok(vec![0.79, 0.56, -0.25, 0.0]));
        assert_eq!(parse_numbers("0,7246526"), Ok(vec![0.7246526]));
        assert_eq!(parse_numbers("1, 2, 3"), Ok(vec![1.0, 2.0, 3.0]));
        assert!(parse_numbers("0.5 NaN").is_err());
        assert_eq!(parse_numbers(" [ ] "), Err(TypedNumberError::Empty));
    }
}
