//! The macro that turns the list of config entries into the `Config` struct, the table of
//! entry names and the parser's bookkeeping of the entries read so far. Entries come in two
//! kinds: those given exactly once, and repeated ones (`obstacle`), given zero or more
//! times, whose values the config keeps in the order of their lines.

macro_rules! config_entries {
    (
        $( $(#[doc = $doc:literal])* $name:ident : $ty:ty, )*
        ;
        repeated {
            $( $(#[doc = $rdoc:literal])* $rname:ident : $rty:ty, )*
        }
    ) => {
        /// Every setting of a run. Field names are the config entries' names; lengths are in
        /// cm, angles in degrees, distances to the target in cm as in the study.
        #[derive(Debug, Clone, PartialEq)]
        #[allow(non_snake_case)] // LWPR's `init_D` keeps the name its users know.
        pub struct Config {
            $( $(#[doc = $doc])* pub $name: $ty, )*
            $( $(#[doc = $rdoc])* pub $rname: Vec<$rty>, )*
        }

        /// Every entry given exactly once, in the order `Config` declares them.
        pub const ENTRY_NAMES: &[&str] = &[$(stringify!($name)),*];
        /// Every entry that may be given any number of times (zero included).
        pub const REPEATED_ENTRY_NAMES: &[&str] = &[$(stringify!($rname)),*];

        /// Entries read so far, with the line each came from.
        #[derive(Debug, Default)]
        #[allow(non_snake_case)]
        pub(super) struct Entries {
            $( $name: Option<($ty, usize)>, )*
            $( $rname: Vec<($rty, usize)>, )*
        }

        impl Entries {
            /// Stores `raw` under `name`; the error says why it can't be.
            pub(super) fn put(&mut self, name: &str, raw: &str, line: usize) -> Result<(), ConfigErrorKind> {
                match name {
                    $(stringify!($name) => {
                        const NAME: &str = stringify!($name);
                        if let Some((_, first_line)) = self.$name {
                            return Err(ConfigErrorKind::Repeated { name: NAME, first_line });
                        }
                        let value = <$ty as ConfigValue>::parse_value(raw)
                            .map_err(|problem| ConfigErrorKind::BadValue { name: NAME, problem })?;
                        self.$name = Some((value, line));
                        Ok(())
                    })*
                    $(stringify!($rname) => {
                        let value = <$rty as ConfigValue>::parse_value(raw).map_err(|problem| {
                            ConfigErrorKind::BadValue { name: stringify!($rname), problem }
                        })?;
                        self.$rname.push((value, line));
                        Ok(())
                    })*
                    _ => Err(ConfigErrorKind::UnknownEntry { name: name.to_string() }),
                }
            }

            /// The entries not given yet.
            pub(super) fn missing(&self) -> Vec<&'static str> {
                let mut missing = Vec::new();
                $( if self.$name.is_none() { missing.push(stringify!($name)); } )*
                missing
            }

            /// The line `name` was given on.
            pub(super) fn line_of(&self, name: &str) -> Option<usize> {
                match name {
                    $(stringify!($name) => self.$name.as_ref().map(|(_, l)| *l),)*
                    $(stringify!($rname) => self.$rname.first().map(|(_, l)| *l),)*
                    _ => None,
                }
            }

            /// The config, once nothing is missing.
            pub(super) fn complete(self) -> Option<Config> {
                Some(Config {
                    $( $name: self.$name?.0, )*
                    $( $rname: self.$rname.into_iter().map(|(value, _)| value).collect(), )*
                })
            }
        }

        impl Config {
            /// Sets one entry from its text without checking it against the other entries
            /// (a repeated entry gets one more value): set every value first, then
            /// [`check`](Config::check) the whole config once.
            pub fn assign(&mut self, name: &str, raw: &str) -> Result<(), ConfigErrorKind> {
                match name {
                    $(stringify!($name) => {
                        self.$name = <$ty as ConfigValue>::parse_value(raw).map_err(|problem| {
                            ConfigErrorKind::BadValue { name: stringify!($name), problem }
                        })?;
                        Ok(())
                    })*
                    $(stringify!($rname) => {
                        let value = <$rty as ConfigValue>::parse_value(raw).map_err(|problem| {
                            ConfigErrorKind::BadValue { name: stringify!($rname), problem }
                        })?;
                        self.$rname.push(value);
                        Ok(())
                    })*
                    _ => Err(ConfigErrorKind::UnknownEntry { name: name.to_string() }),
                }
            }

            /// Every entry with its value as a config file would write it (a repeated
            /// entry once per value).
            pub fn entries(&self) -> Vec<(&'static str, String)> {
                let mut all = vec![$( (stringify!($name), self.$name.render()), )*];
                $( all.extend(self.$rname.iter().map(|v| (stringify!($rname), v.render()))); )*
                all
            }
        }
    };
}
