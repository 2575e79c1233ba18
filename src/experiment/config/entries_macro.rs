//! The macro that turns the declaration of every config entry — its doc line, name, kind,
//! default, unit, scope and rule — into the `Config` struct, its defaults, the parser's
//! assignment by name, the check of each value against its own rule, and the
//! [`Declaration`](super::Declaration) table that `config defaults`, `info` and the docs
//! print. Entries come in two kinds: those holding one value, and repeated ones
//! (`obstacle`), given zero or more times, whose values the config keeps in order.

macro_rules! config_entries {
    (
        $( $(#[doc = $doc:literal])+
           $name:ident : $ty:ty = $default:expr, $unit:literal, $scope:expr, $rule:expr; )*
        repeated {
            $( $(#[doc = $rdoc:literal])+ $rname:ident : $rty:ty, $runit:literal, $rscope:expr; )*
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

        /// Every entry that holds one value, in the order `Config` declares them.
        pub const ENTRY_NAMES: &[&str] = &[$(stringify!($name)),*];
        /// Every entry that may be given any number of times (zero included).
        pub const REPEATED_ENTRY_NAMES: &[&str] = &[$(stringify!($rname)),*];

        impl Config {
            /// Every entry at its declared default (no obstacles).
            pub fn defaults() -> Config {
                Config {
                    $( $name: $default, )*
                    $( $rname: Vec::new(), )*
                }
            }

            /// Sets one entry from its text without checking it against the other entries
            /// (a repeated entry gets one more value): set every value first, then
            /// [`check`](Config::check) the whole config once.
            pub fn assign(&mut self, name: &str, raw: &str) -> Result<(), ConfigErrorKind> {
                match name {
                    $(stringify!($name) => {
                        self.$name = <$ty as ConfigValue>::parse_value(raw).map_err(|problem| {
                            bad_value(stringify!($name), problem, $rule, $unit)
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

            /// Checks every value against its own declared rule, in declaration order.
            pub(super) fn check_each_entry(&self) -> Result<(), ConfigErrorKind> {
                $( meets_rule(stringify!($name), &self.$name, $rule, $unit)?; )*
                Ok(())
            }
        }

        /// Every entry's declaration, in the order `Config` declares them (the repeated
        /// ones last).
        pub fn declarations() -> Vec<Declaration> {
            let defaults = Config::defaults();
            vec![
                $( Declaration {
                    name: stringify!($name),
                    kind: <$ty as ConfigValue>::KIND,
                    unit: $unit,
                    scope: $scope,
                    doc: one_line(concat!($($doc, "\n"),*)),
                    rule: $rule,
                    default: Some(defaults.$name.render()),
                }, )*
                $( Declaration {
                    name: stringify!($rname),
                    kind: <$rty as ConfigValue>::KIND,
                    unit: $runit,
                    scope: $rscope,
                    doc: one_line(concat!($($rdoc, "\n"),*)),
                    rule: Rule::Any,
                    default: None,
                }, )*
            ]
        }
    };
}
