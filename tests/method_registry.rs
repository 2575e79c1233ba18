//! Every method is in every list a user meets it in: `Method::ALL`, the command line's help,
//! its shipped config and `config defaults`. A method added to the enum and missing from one
//! of them fails here.

use eyehand::experiment::Config;
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
