//! Every method is in every list a user meets it in: `Method::ALL`, the command line's help,
//! its shipped config and `config defaults`. A method added to the enum and missing from one
//! of them fails here. Its shipped config is its name alone: `--method X` runs the same values,
//! its own defaults for shared entries declared with its learner.

use eyehand::experiment::{declarations, Config, RunRequest, Scope};
use eyehand::learn::Method;
use std::path::Path;
use std::process::Command;

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

/// The method after `method` in declaration order. The match names every variant, so a new
/// method does not compile until it is placed here, and the chain then checks `Method::ALL`.
fn next(method: Method) -> Option<Method> {
    match method {
        Method::Lin5 => Some(Method::Lin8),
        Method::Lin8 => Some(Method::Nnw),
        Method::Nnw => Some(Method::Ffn),
        Method::Ffn => Some(Method::Kohonen),
        Method::Kohonen => Some(Method::Ik),
        Method::Ik => Some(Method::Lwpr),
        Method::Lwpr => Some(Method::Issgp),
        Method::Issgp => Some(Method::Mlp),
        Method::Mlp => Some(Method::Broyden),
        Method::Broyden => None,
    }
}

fn help(args: &[&str]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_eyehand"))
        .args(args)
        .output()
        .expect("eyehand runs");
    assert!(out.status.success(), "{args:?}");
    String::from_utf8(out.stdout).expect("UTF-8 help")
}

#[test]
fn method_all_lists_every_variant_once_in_order() {
    let chain: Vec<Method> = std::iter::successors(Some(Method::Lin5), |m| next(*m)).collect();
    assert_eq!(chain, Method::ALL);
}

#[test]
fn every_method_is_named_by_the_help_and_parses_back() {
    let run = help(&["run", "--help"]);
    let compare = help(&["compare", "--help"]);
    for method in Method::ALL {
        let name = method.name();
        assert_eq!(name.parse::<Method>(), Ok(method));
        assert!(run.contains(name), "`run --help` does not name {name}");
        assert!(
            compare.contains(name),
            "`compare --help` does not name {name}"
        );
    }
}

#[test]
fn every_method_has_a_shipped_config_that_names_it() {
    for method in Method::ALL {
        let path = Path::new(ROOT).join(format!("configs/{method}.conf"));
        let config = Config::from_file(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        assert_eq!(config.method, method, "{}", path.display());
    }
}

#[test]
fn config_defaults_names_every_method() {
    let defaults = help(&["config", "defaults"]);
    for method in Method::ALL {
        assert!(
            defaults.contains(method.name()),
            "`config defaults` does not name {method}"
        );
    }
}

/// The lines of a config file that are not comments or blank.
fn given_lines(text: &str) -> Vec<String> {
    text.lines()
        .map(|line| line.split('#').next().unwrap_or("").trim())
        .filter(|content| !content.is_empty())
        .map(|content| content.split_whitespace().collect::<Vec<_>>().join(" "))
        .collect()
}

#[test]
fn every_shipped_method_config_gives_its_method_alone() {
    for method in Method::ALL {
        let path = Path::new(ROOT).join(format!("configs/{method}.conf"));
        let text = std::fs::read_to_string(&path).unwrap();
        assert_eq!(
            given_lines(&text),
            [format!("method {method}")],
            "{}: its best settings belong to the method's own defaults",
            path.display()
        );
    }
}

#[test]
fn method_flag_and_shipped_config_resolve_to_the_same_values() {
    for method in Method::ALL {
        let flag = RunRequest {
            method: Some(method),
            ..RunRequest::default()
        };
        let file = RunRequest {
            config: Some(Path::new(ROOT).join(format!("configs/{method}.conf"))),
            ..RunRequest::default()
        };
        let (by_flag, _) = flag
            .config()
            .unwrap_or_else(|e| panic!("--method {method}: {e}"));
        let (by_file, _) = file
            .config()
            .unwrap_or_else(|e| panic!("{method}.conf: {e}"));
        assert_eq!(by_flag.entries(), by_file.entries(), "{method}");
        assert_eq!(Config::defaults_for(method), Ok(by_flag), "{method}");
    }
    // A method given over another's config takes its own defaults, not the file's method's.
    let over = RunRequest {
        config: Some(Path::new(ROOT).join("configs/ffn.conf")),
        method: Some(Method::Lin5),
        ..RunRequest::default()
    };
    assert_eq!(over.config().unwrap().0, Config::default_config());
}

#[test]
fn each_methods_own_defaults_are_entries_it_uses_within_their_rules() {
    let declared = declarations();
    let mut count = 0;
    for method in Method::ALL {
        for (name, value) in method.facts().shared_defaults {
            count += 1;
            let entry = declared.iter().find(|d| d.name == *name);
            let entry = entry.unwrap_or_else(|| panic!("{method}: `{name}` is no entry"));
            let applies = match entry.scope {
                Scope::All => true,
                Scope::Methods(methods) => methods.contains(&method),
                _ => false,
            };
            assert!(applies, "{method}: `{name}` ({}) is not its", entry.scope);
            let set = RunRequest {
                sets: vec![
                    ("method".into(), method.to_string()),
                    (name.to_string(), value.to_string()),
                ],
                ..RunRequest::default()
            };
            let (config, _) = set
                .config()
                .unwrap_or_else(|e| panic!("{method}: {name} {value}: {e}"));
            let written = config.entries().into_iter().find(|(n, _)| n == name);
            let written = written.map(|(_, v)| v);
            assert_eq!(written.as_deref(), Some(*value), "{method}: {name}");
            assert_ne!(
                entry.default.as_deref(),
                Some(*value),
                "{method}: {name} {value} is the entry's own default already"
            );
        }
    }
    assert!(
        count >= 6,
        "lin8, nnw, ffn, kohonen, ik and broyden have their own"
    );
}
