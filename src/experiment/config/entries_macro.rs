//! The macro that turns the list of config entries into the `Config` struct, the table of
//! entry names and the parser's bookkeeping of the entries read so far.

macro_rules! config_entries {
    ($( $(#[doc = $doc:literal])* $name:ident : $ty:ty, )*) => {
        /// Every setting of a run. Field names are the config entries' names; lengths are in
        /// cm, angles in degrees, distances to the target in cm as in the study.
        #[derive(Debug, Clone, PartialEq)]
        pub struct Config {
            $( $(#[doc = $doc])* pub $name: $ty, )*
        }

        /// Every entry name, in the order `Config` declares them.
        pub const ENTRY_NAMES: &[&str] = &[$(stringify!($name)),*];

        /// Entries read so far, with the line each came from.
        #[derive(Debug, Default)]
        pub(super) struct Entries {
            $( $name: Option<($ty, usize)>, )*
        }

        impl Entries {
            /// Stores `raw` under `name`; the error says why it can't be.
            pub(super) fn put(&mut self, name: &str, raw: &str, line: usize) -> Result<(), String> {
                match name {
                    $(stringify!($name) => {
                        if let Some((_, first)) = self.$name {
                            return Err(format!("`{name}` is given twice (first on line {first})"));
                        }
                        let value = <$ty as ConfigValue>::parse_value(raw)
                            .map_err(|e| format!("{name}: {e}"))?;
                        self.$name = Some((value, line));
                        Ok(())
                    })*
                    _ => Err(format!("unknown entry `{name}`")),
                }
            }

            pub(super) fn missing(&self) -> Vec<&'static str> {
                let mut missing = Vec::new();
                $( if self.$name.is_none() { missing.push(stringify!($name)); } )*
                missing
            }

            pub(super) fn line_of(&self, name: &str) -> Option<usize> {
                match name {
                    $(stringify!($name) => self.$name.as_ref().map(|(_, l)| *l),)*
                    _ => None,
                }
            }

            /// The config, once nothing is missing.
            pub(super) fn complete(self) -> Option<Config> {
                Some(Config { $( $name: self.$name?.0, )* })
            }
        }

        impl Config {
            /// Sets one entry from its text, as a config line or a command-line override would.
            pub fn set(&mut self, name: &str, raw: &str) -> Result<(), String> {
                match name {
                    $(stringify!($name) => {
                        self.$name = <$ty as ConfigValue>::parse_value(raw)
                            .map_err(|e| format!("{name}: {e}"))?;
                    })*
                    _ => return Err(format!("unknown entry `{name}`")),
                }
                self.validate().map_err(|(_, reason)| reason)
            }

            /// Every entry with its value as a config file would write it.
            pub fn entries(&self) -> Vec<(&'static str, String)> {
                vec![$( (stringify!($name), self.$name.render()), )*]
            }
        }
    };
}
