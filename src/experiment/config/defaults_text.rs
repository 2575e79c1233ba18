//! The declarations written out for people: a complete config at its defaults, one
//! commented entry a line (`eyehand config defaults`), and the table of docs/CONFIG.md.

use super::{declarations, Declaration, Scope};

/// What `config defaults` prints first.
const HEADER: &str = "\
# eyehand config: every entry at its default (`eyehand config defaults`).
# Format (the study's appendix A.2): one `name value` per line, `#` starts a comment, blank
# lines are allowed, any order. A file needs only the entries it changes; an unknown or
# repeated name or a bad value stops the program with file:line: reason. Above each entry:
# what it does [what it applies to; unit; the rule its value must meet].
";

/// A complete config at the declared defaults, each entry under a comment with its doc,
/// scope, unit and rule; a repeated entry (`obstacle`) as a commented example, and so an
/// entry eyehand accepts but does not implement.
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
            Some(value) => text += &format!("{:width$}{value}\n", declaration.name),
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

/// The Markdown table of every entry: name, kind, default, unit, what it applies to, its
/// rule and what it does.
pub fn docs_table() -> String {
    let mut table = "| entry | kind | default | unit | applies to | rule | what it does |\n\
                     |---|---|---|---|---|---|---|\n"
        .to_string();
    for d in declarations() {
        let default = d.default.as_deref().unwrap_or("none (repeatable)");
        let rule = d.rule.text(d.unit).unwrap_or_default();
        let doc = d.doc.replace('|', "\\|");
        table += &format!(
            "| `{}` | {} | `{default}` | {} | {} | {rule} | {doc} |\n",
            d.name, d.kind, d.unit, d.scope
        );
    }
    table
}
