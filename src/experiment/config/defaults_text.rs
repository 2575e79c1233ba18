//! The declarations written out for people: a complete config at its defaults, one
//! commented entry a line (`eyehand config defaults`), and the table of docs/CONFIG.md.

use super::method_defaults::method_defaults_of;
use super::{declarations, Declaration, Scope};

/// What `config defaults` prints first.
const HEADER: &str = "\
# eyehand config: every entry at its default (`eyehand config defaults`).
# Format (the study's appendix A.2): one `name value` per line, `#` starts a comment, blank
# lines are allowed, any order. A file needs only the entries it changes; an unknown or
# repeated name or a bad value stops the program with file:line: reason. Above each entry:
# what it does [what it applies to; unit; the rule its value must meet]. An entry some
# methods have their own default for is left commented, so each method runs its own.
";

/// A complete config at the declared defaults, each entry under a comment with its doc,
/// scope, unit and rule; a repeated entry (`obstacle`) as a commented example, and so an
/// entry eyehand accepts but does not implement, and one some methods have their own
/// default for (with theirs), so the file's `method` still picks it.
pub fn defaults_text() -> String {
    let all = declarations();
    let width = all.iter().map(|d| d.name.len()).max().unwrap_or(0) + 2;
    let mut text = HEADER.to_string();
    for declaration in &all {
        text += &format!("\n# {} [{}]\n", declaration.doc, facts(declaration));
        match &declaration.default {
            Some(value) if declaration.scope == Scope::Unused => {
                let line = format!("{:width$}{value}", declaration.name);
                text += &format!("# {line}   (accepted, but unused)\n");
            }
            Some(value) => match by_method(declaration.name) {
                Some(theirs) => {
                    let line = format!("{:width$}{value}", declaration.name);
                    text += &format!("# {line}   (methods' own: {theirs})\n");
                }
                None => text += &format!("{:width$}{value}\n", declaration.name),
            },
            None => {
                let line = format!("{:width$}{}", declaration.name, declaration.kind);
                text += &format!("# {line}   (any number of lines, none by default)\n");
            }
        }
    }
    text
}

/// The bracketed facts of an entry: its scope, unit and rule.
fn facts(declaration: &Declaration) -> String {
    let mut parts = vec![declaration.scope.to_string()];
    if !declaration.unit.is_empty() {
        parts.push(declaration.unit.to_string());
    }
    if let Some(rule) = declaration.rule.text(declaration.unit) {
        parts.push(rule);
    }
    parts.join("; ")
}

/// The methods with their own default for entry `name`, grouped by value in the order of
/// `Method::ALL` ("nnw, ik, broyden 1000; ffn, kohonen 20000"); `None` when no method has
/// one.
fn by_method(name: &str) -> Option<String> {
    let mut groups: Vec<(&str, Vec<String>)> = Vec::new();
    for (method, value) in method_defaults_of(name) {
        match groups.iter_mut().find(|(v, _)| *v == value) {
            Some((_, methods)) => methods.push(method.to_string()),
            None => groups.push((value, vec![method.to_string()])),
        }
    }
    let groups: Vec<String> = groups
        .iter()
        .map(|(value, methods)| format!("{} {value}", methods.join(", ")))
        .collect();
    (!groups.is_empty()).then(|| groups.join("; "))
}

/// The Markdown table of every entry: name, kind, default (and the methods' own), unit,
/// what it applies to, its rule and what it does.
pub fn docs_table() -> String {
    let mut table = "| entry | kind | default | unit | applies to | rule | what it does |\n\
                     |---|---|---|---|---|---|---|\n"
        .to_string();
    for d in declarations() {
        let mut default = format!("`{}`", d.default.as_deref().unwrap_or("none (repeatable)"));
        if let Some(theirs) = by_method(d.name) {
            default += &format!("; {theirs}");
        }
        let rule = d.rule.text(d.unit).unwrap_or_default();
        let doc = d.doc.replace('|', "\\|");
        table += &format!(
            "| `{}` | {} | {default} | {} | {} | {rule} | {doc} |\n",
            d.name, d.kind, d.unit, d.scope
        );
    }
    table
}
