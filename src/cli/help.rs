//! The command line's help in the user's language: clap builds the commands from the
//! derive's doc comments (the English of the source); this walk replaces every text a user
//! reads in `--help` with the catalogue's. Clap's own words ("Usage", "Options", "Print
//! help", "[default: …]") are replaced too: the usage through the help template, the
//! headings through each argument's heading, the help and version flags by our own, and
//! the defaults and possible values by lines written here. Clap's error messages stay
//! English (clap has no hook for their words).
//!
//! Message ids: `cli-{command path}` for a command's about (`cli-explain`,
//! `cli-bench-render`), `cli-arg-{path}-{argument}` for an argument (`cli-arg-app-file`,
//! `cli-arg-explain-worksheet`), `cli-value-{value}` for a value's description
//! (`cli-value-f32`).

use clap::builder::{PossibleValue, StyledStr};
use clap::{Arg, ArgAction, Command};

use crate::locale::tr;
use crate::t;

/// The path of the root command in message ids.
pub const ROOT: &str = "app";

/// The message id of argument `arg` of the command at `path` ("app", "explain",
/// "bench-render"). The language options, shared by every command, have their own ids.
pub fn arg_message_id(path: &str, arg: &str) -> String {
    match arg {
        "lang" => "cli-lang".to_string(),
        "decimal" => "cli-decimal".to_string(),
        "memory_budget" => "cli-memory-budget".to_string(),
        _ => format!("cli-arg-{path}-{arg}"),
    }
}

/// The message id of a command's about: the root's is `cli-about`.
pub fn about_message_id(path: &str) -> String {
    if path == ROOT { "cli-about".to_string() } else { format!("cli-{path}") }
}

/// The message id of a possible value's description.
pub fn value_message_id(value: &str) -> String {
    format!("cli-value-{value}")
}

/// The arguments a user reads about in `path`'s help, with the id each is described by:
/// every argument but clap's help and version flags and the globals, which are described
/// once, on the root.
pub fn described_arguments(cmd: &Command, path: &str) -> Vec<(String, String)> {
    cmd.get_arguments()
        .filter(|a| !matches!(a.get_id().as_str(), "help" | "version"))
        .filter(|a| path == ROOT || !a.is_global_set())
        .map(|a| (a.get_id().to_string(), arg_message_id(path, a.get_id().as_str())))
        .collect()
}

/// The possible values of an argument that have a description (flags' true/false have none).
pub fn described_values(arg: &Arg) -> Vec<PossibleValue> {
    arg.get_possible_values().into_iter().filter(|v| v.get_help().is_some()).collect()
}

/// Every command of the tree, with its path in message ids.
pub fn command_paths(root: &Command) -> Vec<(String, &Command)> {
    let mut out = vec![(ROOT.to_string(), root)];
    let mut at = 0;
    while at < out.len() {
        let (path, cmd) = (out[at].0.clone(), out[at].1);
        for sub in cmd.get_subcommands().filter(|s| s.get_name() != "help") {
            let sub_path = if path == ROOT { sub.get_name().to_string() } else { format!("{path}-{}", sub.get_name()) };
            out.push((sub_path, sub));
        }
        at += 1;
    }
    out
}

/// `root` with every text of its help in the current language.
pub fn localised(root: Command) -> Command {
    localise(root, ROOT)
}

fn localise(cmd: Command, path: &str) -> Command {
    let template =
        format!("{{before-help}}{{about-with-newline}}\n{} {{usage}}\n\n{{all-args}}{{after-help}}", t!("cli-usage"));
    let mut cmd = cmd
        .about(tr(&about_message_id(path)))
        .long_about(None)
        .help_template(template)
        .subcommand_help_heading(t!("cli-heading-commands"))
        .disable_help_flag(true)
        .arg(Arg::new("help").short('h').long("help").action(ArgAction::Help).help(t!("cli-flag-help")));
    if path == ROOT {
        cmd = cmd
            .disable_version_flag(true)
            .arg(Arg::new("version").short('V').long("version").action(ArgAction::Version).help(t!("cli-flag-version")))
            .disable_help_subcommand(true)
            .subcommand(Command::new("help").about(t!("cli-help-command")).arg(Arg::new("command").num_args(0..)));
    }
    let arguments = t!("cli-heading-arguments");
    let options = t!("cli-heading-options");
    for (id, message) in described_arguments(&cmd, path) {
        let (arguments, options) = (arguments.clone(), options.clone());
        cmd = cmd.mut_arg(id, |a| described(a, &message, arguments, options));
    }
    // Clap's own flags, added above, go under the options' heading too.
    for id in ["help", "version"] {
        if cmd.get_arguments().any(|a| a.get_id() == id) {
            let options = options.clone();
            cmd = cmd.mut_arg(id, |a| a.help_heading(options));
        }
    }
    let subs: Vec<String> = cmd.get_subcommands().map(|s| s.get_name().to_string()).filter(|n| n != "help").collect();
    for name in subs {
        let sub_path = if path == ROOT { name.clone() } else { format!("{path}-{name}") };
        cmd = cmd.mut_subcommand(name, |s| localise(s, &sub_path));
    }
    cmd
}

/// One argument described from the catalogue: its help, its values and its default as
/// lines of ours, under the localised heading.
fn described(arg: Arg, message: &str, arguments: String, options: String) -> Arg {
    let mut help = tr(message);
    let mut long = help.clone();
    let values = described_values(&arg);
    if !values.is_empty() {
        let names: Vec<&str> = values.iter().map(clap::builder::PossibleValue::get_name).collect();
        help.push(' ');
        help.push_str(&t!("cli-possible-values", values = names.join(", ")));
        long.push('\n');
        for v in &values {
            long.push_str(&format!("\n- {}: {}", v.get_name(), tr(&value_message_id(v.get_name()))));
        }
    }
    let defaults: Vec<String> = arg.get_default_values().iter().map(|v| v.to_string_lossy().into_owned()).collect();
    let shows_default = !defaults.is_empty() && arg.get_action().takes_values();
    if shows_default {
        let line = t!("cli-default", value = defaults.join(", "));
        help.push(' ');
        help.push_str(&line);
        long.push_str(if values.is_empty() { " " } else { "\n" });
        long.push_str(&line);
    }
    let heading = if arg.is_positional() { arguments } else { options };
    let takes_values = arg.get_action().takes_values();
    arg.help(StyledStr::from(help))
        .long_help(StyledStr::from(long))
        .hide_possible_values(takes_values)
        .hide_default_value(takes_values)
        .help_heading(heading)
}

/// `phonglab help [COMMAND…]`: the long help of the command named, or of the root.
pub fn print_help_of<'a>(root: &mut Command, names: impl Iterator<Item = &'a String>) {
    root.build();
    let mut cmd = root;
    for name in names {
        if cmd.find_subcommand(name).is_none() {
            break;
        }
        cmd = cmd.find_subcommand_mut(name).expect("found just above");
    }
    let _ = cmd.print_long_help();
}
