//! The command line's own errors (a value out of range, a missing value, an unknown
//! option...) in the catalogue's words, in the language asked for: clap writes them in
//! English, so its error's kind and context (the argument, the value, the values it takes)
//! are said again through the catalogue. Kinds not said here keep clap's text. The exit
//! code stays clap's (2).

use clap::error::{ContextKind, ContextValue, ErrorKind};

use crate::t;

/// The message for clap's error `e` in the current language, ending with where the help
/// is (`phonglab exercise --help`, `command` being the subcommand the line named); `None`
/// for a kind said by clap itself.
pub fn message(e: &clap::Error, command: Option<&str>) -> Option<String> {
    let said = match e.kind() {
        ErrorKind::InvalidValue => invalid_value(e),
        ErrorKind::ValueValidation => refused_value(e),
        ErrorKind::UnknownArgument => unknown_argument(e),
        // clap names neither the argument nor the bytes.
        ErrorKind::InvalidUtf8 => Some(t!("arg-error-invalid-utf8")),
        ErrorKind::InvalidSubcommand => {
            let name = shown(&string(e, ContextKind::InvalidSubcommand)?);
            let said = match string(e, ContextKind::Custom).as_deref() {
                Some("arg-error-unknown-command-or-file") => t!("arg-error-unknown-command-or-file", name = name),
                _ => t!("arg-error-unknown-command", name = name),
            };
            Some(with_suggestion(said, e, ContextKind::SuggestedSubcommand))
        }
        ErrorKind::MissingRequiredArgument => {
            let args: Vec<String> = strings(e, ContextKind::InvalidArg).iter().map(|a| arg_name(a)).collect();
            (!args.is_empty()).then(|| t!("arg-error-missing", args = args.join(", ")))
        }
        ErrorKind::ArgumentConflict => {
            let arg = arg_name(&string(e, ContextKind::InvalidArg)?);
            let other: Vec<String> = strings(e, ContextKind::PriorArg).iter().map(|a| arg_name(a)).collect();
            // `--level 3 --level 4`: clap calls an option given twice a conflict with itself.
            if other == [arg.clone()] {
                return Some(finish(t!("arg-error-twice", arg = arg), command));
            }
            Some(t!("arg-error-conflict", arg = arg, other = other.join(", ")))
        }
        ErrorKind::NoEquals | ErrorKind::TooFewValues | ErrorKind::WrongNumberOfValues => {
            Some(t!("arg-error-missing-value", arg = arg_name(&string(e, ContextKind::InvalidArg)?)))
        }
        _ => None,
    }?;
    Some(finish(said, command))
}

/// clap's error for `name`, which is no command of `root` (`message` says it with the
/// catalogue's `id`, `arg-error-unknown-command` or, where a file was expected too,
/// `arg-error-unknown-command-or-file`), with the closest command as the suggestion (the
/// measure clap suggests with: Jaro similarity over 0.7).
pub fn unknown_command(root: &mut clap::Command, name: &str, id: &'static str) -> clap::Error {
    root.build();
    let closest = root
        .get_subcommands()
        .map(|c| (strsim::jaro(name, c.get_name()), c.get_name().to_string()))
        .filter(|(score, _)| *score > 0.7)
        .max_by(|a, b| a.0.total_cmp(&b.0))
        .map(|(_, n)| n);
    let mut e = clap::Error::new(ErrorKind::InvalidSubcommand).with_cmd(root);
    e.insert(ContextKind::InvalidSubcommand, ContextValue::String(name.to_string()));
    e.insert(ContextKind::Custom, ContextValue::String(id.to_string()));
    if let Some(c) = closest {
        e.insert(ContextKind::SuggestedSubcommand, ContextValue::Strings(vec![c]));
    }
    e
}

/// `said` as the refusal prints it, then where the help is.
fn finish(said: String, command: Option<&str>) -> String {
    let help = match command {
        Some(c) => format!("phonglab {c} --help"),
        None => "phonglab --help".to_string(),
    };
    format!("phonglab: {said}\n{}\n", t!("arg-error-more", help = help))
}

/// A value not among those the argument takes, or no value at all.
fn invalid_value(e: &clap::Error) -> Option<String> {
    let arg = arg_name(&string(e, ContextKind::InvalidArg)?);
    let value = string(e, ContextKind::InvalidValue).unwrap_or_default();
    if value.is_empty() {
        return Some(t!("arg-error-missing-value", arg = arg));
    }
    let values = strings(e, ContextKind::ValidValue).join(", ");
    let said = t!("arg-error-invalid-value", arg = arg, value = shown(&value), values = values);
    Some(with_suggestion(said, e, ContextKind::SuggestedValue))
}

/// A value its parser refused: out of range, not a number, or refused by phonglab's own
/// parser, whose reason is already in the catalogue's words.
fn refused_value(e: &clap::Error) -> Option<String> {
    let arg = arg_name(&string(e, ContextKind::InvalidArg)?);
    let value = string(e, ContextKind::InvalidValue).unwrap_or_default();
    let source = std::error::Error::source(e)?;
    if let Some(w) = source.downcast_ref::<NotInRange>() {
        let (low, high) = (phonglab_core::locale::grouped(w.low), phonglab_core::locale::grouped(w.high));
        return Some(t!("arg-error-out-of-range", arg = arg, low = low, high = high, value = shown(&value)));
    }
    if source.downcast_ref::<std::num::ParseIntError>().is_some() {
        return Some(t!("arg-error-not-whole", arg = arg, value = shown(&value)));
    }
    if source.downcast_ref::<std::num::ParseFloatError>().is_some() {
        return Some(t!("arg-error-not-number", arg = arg, value = shown(&value)));
    }
    // phonglab's parsers start their reason with the value ("\"virgula\": point or
    // comma"), which the message says already.
    let reason = source.to_string();
    let reason = reason.strip_prefix(&format!("{}: ", shown(&value))).map_or(reason.clone(), str::to_string);
    if let Some((low, high)) = range_of(&reason) {
        return Some(t!("arg-error-out-of-range", arg = arg, low = low, high = high, value = shown(&value)));
    }
    Some(t!("arg-error-refused-value", arg = arg, value = shown(&value), reason = reason))
}

/// A value that is not a whole number from `low` to `high` ([`whole`]): the refusal says
/// the range in words, whatever was wrong with the value (`-1`, `1e20`, twenty digits).
#[derive(Debug)]
pub struct NotInRange {
    /// The smallest value taken.
    pub low: u64,
    /// The largest value taken.
    pub high: u64,
}

impl std::fmt::Display for NotInRange {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "not a whole number from {} to {}", self.low, self.high)
    }
}

impl std::error::Error for NotInRange {}

/// A value parser for a whole number from `low` to `high`, refusing anything else
/// ([`NotInRange`]) so that the refusal names the range: clap's own says only "a whole
/// number" for a value past the type's range (`--count 99999999999999999999`) or not
/// whole (`--variants 1e20`). Give the argument `allow_negative_numbers` too, so that
/// `--seed -1` is this value refused, not an unknown option `-1`.
pub fn whole(low: u64, high: u64) -> impl Fn(&str) -> Result<u64, NotInRange> + Clone + Send + Sync + 'static {
    move |text: &str| {
        text.trim().parse::<u64>().ok().filter(|n| (low..=high).contains(n)).ok_or(NotInRange { low, high })
    }
}

/// The bounds of clap's range refusal, "0 is not in 1..=100" (or `1..101`, an upper bound
/// left out): (1, 100).
fn range_of(reason: &str) -> Option<(String, String)> {
    let (_, bounds) = reason.split_once(" is not in ")?;
    let (low, high) = bounds.split_once("..")?;
    let low: i128 = low.trim().parse().ok()?;
    let high: i128 = match high.strip_prefix('=') {
        Some(h) => h.trim().parse().ok()?,
        None => high.trim().parse::<i128>().ok()? - 1,
    };
    Some((low.to_string(), high.to_string()))
}

fn unknown_argument(e: &clap::Error) -> Option<String> {
    let typed = string(e, ContextKind::InvalidArg)?;
    let arg = shown(&typed);
    // A word that is no option (`exercise extra`): an argument the command does not take.
    if !typed.starts_with('-') {
        return Some(t!("arg-error-unexpected", arg = arg));
    }
    Some(with_suggestion(t!("arg-error-unknown", arg = arg), e, ContextKind::SuggestedArg))
}

/// `said`, then "Did you mean X?" where clap has a suggestion of that kind.
fn with_suggestion(said: String, e: &clap::Error, kind: ContextKind) -> String {
    match strings(e, kind).first() {
        Some(s) => format!("{said} {}", t!("arg-error-did-you-mean", suggestion = arg_name(s))),
        None => said,
    }
}

/// One text of the error's context.
fn string(e: &clap::Error, kind: ContextKind) -> Option<String> {
    match e.get(kind)? {
        ContextValue::String(s) => Some(s.clone()),
        ContextValue::Strings(s) => s.first().cloned(),
        ContextValue::StyledStr(s) => Some(s.to_string()),
        _ => None,
    }
}

/// The texts of the error's context.
fn strings(e: &clap::Error, kind: ContextKind) -> Vec<String> {
    match e.get(kind) {
        Some(ContextValue::String(s)) => vec![s.clone()],
        Some(ContextValue::Strings(s)) => s.clone(),
        Some(ContextValue::StyledStr(s)) => vec![s.to_string()],
        Some(ContextValue::StyledStrs(s)) => s.iter().map(ToString::to_string).collect(),
        _ => Vec::new(),
    }
}

/// An argument as people type it: `--variants`, not clap's `--variants <VARIANTS>` (a
/// positional one keeps its `<NAME>`).
fn arg_name(arg: &str) -> String {
    let name = if arg.starts_with('-') { arg.split(' ').next().unwrap_or(arg) } else { arg };
    phonglab_core::escape::terminal::text(name)
}

/// What the user typed, quoted, as the terminal may show it (no escape sequence).
fn shown(value: &str) -> String {
    format!("\"{}\"", phonglab_core::escape::terminal::text(value))
}

#[cfg(test)]
mod tests {
    use super::range_of;

    #[test]
    fn whole_numbers_are_taken_only_in_their_range() {
        let count = super::whole(1, 1000);
        assert_eq!(count("7").ok(), Some(7));
        assert_eq!(count("1000").ok(), Some(1000));
        for bad in ["0", "1001", "-1", "1e20", "99999999999999999999", "x", ""] {
            assert!(count(bad).is_err(), "{bad:?}");
        }
        assert_eq!(super::whole(0, u64::MAX)(&u64::MAX.to_string()).ok(), Some(u64::MAX));
    }

    #[test]
    fn clap_ranges_are_read_inclusive() {
        assert_eq!(range_of("0 is not in 1..=100"), Some(("1".into(), "100".into())));
        assert_eq!(range_of("9 is not in 1..6"), Some(("1".into(), "5".into())));
        assert_eq!(range_of("invalid digit found in string"), None);
    }
}
