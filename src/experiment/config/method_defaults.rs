//! A method's own defaults for entries it shares with other methods (`trials`,
//! `change_fit_patterns`, …), declared in its folder beside its `MethodFacts`: an entry's
//! value is the one a config line, `--set` or flag gives, else the default of the config's
//! method, else the entry's own. So `--method X` runs the values of `configs/X.conf`.

use super::{Config, ConfigErrorKind, Sources};
use crate::learn::Method;

/// `method`'s own default of entry `name` as a config file writes it, if it declares one.
pub(super) fn method_default(method: Method, name: &str) -> Option<&'static str> {
    method
        .facts()
        .shared_defaults
        .iter()
        .find(|(entry, _)| *entry == name)
        .map(|(_, value)| *value)
}

/// The methods that declare their own default for entry `name`, each with its value, in
/// the order of [`Method::ALL`].
pub(super) fn method_defaults_of(name: &str) -> Vec<(Method, &'static str)> {
    Method::ALL
        .into_iter()
        .filter_map(|method| method_default(method, name).map(|value| (method, value)))
        .collect()
}

/// Every entry some method declares its own default for, once each.
fn entries_with_method_defaults() -> Vec<&'static str> {
    let mut names = Vec::new();
    for method in Method::ALL {
        for (name, _) in method.facts().shared_defaults {
            if !names.contains(name) {
                names.push(*name);
            }
        }
    }
    names
}

impl Config {
    /// The declared defaults with `method` and its own defaults in place: the config a
    /// file holding only `method <method>` gives.
    pub fn defaults_for(method: Method) -> Result<Config, ConfigErrorKind> {
        let mut config = Config {
            method,
            ..Config::defaults()
        };
        config.take_method_defaults(&Sources::default())?;
        Ok(config)
    }

    /// Sets every entry some method declares its own default for, and that `sources`
    /// does not record as given, to the default of this config's method: its own, else the
    /// entry's. Called once every line, `--set` and flag is in, so the method may be given
    /// anywhere among them.
    pub(crate) fn take_method_defaults(
        &mut self,
        sources: &Sources,
    ) -> Result<(), ConfigErrorKind> {
        let entry_defaults = Config::defaults().entries();
        for name in entries_with_method_defaults() {
            if sources.of(name).is_some() {
                continue;
            }
            let value = match method_default(self.method, name) {
                Some(own) => own.to_string(),
                None => entry_defaults
                    .iter()
                    .find(|(entry, _)| *entry == name)
                    .map(|(_, value)| value.clone())
                    .ok_or_else(|| ConfigErrorKind::UnknownEntry {
                        name: name.to_string(),
                    })?,
            };
            self.assign(name, &value)?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::experiment::config::Source;

    #[test]
    fn a_method_takes_its_own_defaults_and_a_given_value_wins() {
        let ffn = Config::defaults_for(Method::Ffn).unwrap();
        assert_eq!(ffn.trials, 20000);
        let lin8 = Config::defaults_for(Method::Lin8).unwrap();
        assert_eq!((lin8.trials, lin8.change_fit_patterns), (10000, 600));
        assert_eq!(Config::defaults_for(Method::Lin5), Ok(Config::defaults()));

        let (given, _) = Config::read("trials 10000\nmethod ffn\n", "given.conf").unwrap();
        assert_eq!(
            given.trials, 10000,
            "a line at the entry's default still wins"
        );
        let mut back = ffn.clone();
        back.method = Method::Lin5;
        back.take_method_defaults(&Sources::default()).unwrap();
        assert_eq!(
            back,
            Config::defaults(),
            "another method's defaults are undone"
        );
        let mut sources = Sources::default();
        sources.record("trials", Source::Set);
        let mut kept = ffn;
        kept.method = Method::Lin5;
        kept.take_method_defaults(&sources).unwrap();
        assert_eq!(kept.trials, 20000, "a recorded value is kept");
    }

    #[test]
    fn the_entries_list_each_method_default_once() {
        assert_eq!(method_default(Method::Kohonen, "trials"), Some("20000"));
        assert_eq!(method_default(Method::Lin5, "trials"), None);
        let trials: Vec<Method> = method_defaults_of("trials")
            .into_iter()
            .map(|(m, _)| m)
            .collect();
        assert_eq!(
            trials,
            [
                Method::Nnw,
                Method::Ffn,
                Method::Kohonen,
                Method::Ik,
                Method::Broyden
            ]
        );
        let names = entries_with_method_defaults();
        assert_eq!(names, ["change_fit_patterns", "trials"]);
    }
}
