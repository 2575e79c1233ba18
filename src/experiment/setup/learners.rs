//! Each learner's settings from the config entries of the same names.

use crate::experiment::Config;
use crate::learn::change::{ChangeRecovery, ChangeSettings, DetectorSettings};
use crate::learn::{
    BroydenSettings, FfnSettings, IssgpSettings, KohonenSettings, Lin5Settings, Lin8Settings,
    LwprSettings, MergeStrategy, MlpSettings, NestedSettings, NnwSettings, PatternSettings,
    PerceptronSettings, TreeSettings,
};

/// `lin5`: `boundary_0` … `boundary_4`, the tree, perceptron, merge and change entries,
/// `minimal_joint_move` and `seed`.
pub fn lin5_settings(config: &Config) -> Lin5Settings {
    Lin5Settings {
        bounds: input_bounds(config),
        nested: nested_settings(config),
        perceptron: perceptron_settings(config),
    }
}

/// `lin8`: lin5's entries with `boundary_0` … `boundary_7` and `error_area_shrink`.
pub fn lin8_settings(config: &Config) -> Lin8Settings {
    Lin8Settings {
        bounds: input_bounds(config),
        error_area_shrink: config.error_area_shrink,
        nested: nested_settings(config),
        perceptron: perceptron_settings(config),
    }
}

/// `nnw`: lin5's bounds and tree entries with `hidden_units` and `wrange`.
pub fn nnw_settings(config: &Config) -> NnwSettings {
    NnwSettings {
        bounds: input_bounds(config),
        nested: nested_settings(config),
        hidden_units: config.hidden_units,
        wrange: config.wrange,
    }
}

/// `ffn`: `ffn_hidden_units`, `wrange`, `ffn_window`, `ffn_cg_iterations` and
/// `minimal_joint_move`.
pub fn ffn_settings(config: &Config) -> FfnSettings {
    FfnSettings {
        hidden_units: config.ffn_hidden_units,
        wrange: config.wrange,
        window: config.ffn_window,
        cg_iterations: config.ffn_cg_iterations,
        patterns: pattern_settings(config),
    }
}

/// `kohonen`: `kohonen_side`, `kohonen_anneal_patterns` and `minimal_joint_move`.
pub fn kohonen_settings(config: &Config) -> KohonenSettings {
    KohonenSettings {
        side: config.kohonen_side,
        anneal_patterns: config.kohonen_anneal_patterns,
        patterns: pattern_settings(config),
        ..KohonenSettings::default()
    }
}

/// `lwpr`: `init_D`, `init_alpha`, `w_gen`, `w_prune`, the λ entries, `diag_only`,
/// `meta`, `meta_rate`, `penalty`, `add_threshold`, `norm_out`, `minimal_joint_move`, and
/// the `change_*` entries under `merge_strategy change_detection`.
pub fn lwpr_settings(config: &Config) -> LwprSettings {
    LwprSettings {
        init_d: config.init_D,
        init_alpha: config.init_alpha,
        w_gen: config.w_gen,
        w_prune: config.w_prune,
        init_lambda: config.init_lambda,
        tau_lambda: config.tau_lambda,
        final_lambda: config.final_lambda,
        diag_only: config.diag_only == 1,
        meta: config.meta == 1,
        meta_rate: config.meta_rate,
        penalty: config.penalty,
        add_threshold: config.add_threshold,
        norm_out: config.norm_out,
        patterns: pattern_settings(config),
        change_detection: watch_settings(config),
    }
}

/// `issgp`: the `issgp_*` entries, `norm_out`, `minimal_joint_move`, `seed`, and the
/// `change_*` entries under `merge_strategy change_detection`.
pub fn issgp_settings(config: &Config) -> IssgpSettings {
    IssgpSettings {
        features: config.issgp_features,
        length_scales: config.issgp_length_scales,
        noise: config.issgp_noise,
        signal: config.issgp_signal,
        forgetting: config.issgp_forgetting,
        anchored: config.issgp_anchored == 1,
        norm_out: config.norm_out,
        patterns: pattern_settings(config),
        seed: config.seed,
        change_detection: watch_settings(config),
    }
}

/// `mlp`: the `mlp_*` entries, `norm_out`, `minimal_joint_move`, `seed`, and the
/// `change_*` entries under `merge_strategy change_detection`.
pub fn mlp_settings(config: &Config) -> MlpSettings {
    MlpSettings {
        hidden: config.mlp_hidden,
        rate: config.mlp_rate,
        batch: config.mlp_batch,
        steps_per_trial: config.mlp_steps_per_trial,
        buffer: config.mlp_buffer,
        anchored: config.mlp_anchored == 1,
        norm_out: config.norm_out,
        patterns: pattern_settings(config),
        seed: config.seed,
        change_detection: watch_settings(config),
    }
}

/// `broyden`: the `broyden_*` entries.
pub fn broyden_settings(config: &Config) -> BroydenSettings {
    BroydenSettings {
        update: config.broyden_update,
        rate: config.broyden_rate,
        forgetting: config.broyden_forgetting,
        damping: config.broyden_damping,
        max_step_deg: config.broyden_max_step,
        probe_deg: config.broyden_probe,
    }
}

/// The change watch of a single-model learner: the `change_*` entries under
/// `merge_strategy change_detection` with `change_recovery forget`, none otherwise (under
/// `correct` the learner's [`CorrectedLearner`](crate::learn::change::CorrectedLearner)
/// watches it).
fn watch_settings(config: &Config) -> Option<ChangeSettings> {
    (config.merge_strategy == MergeStrategy::ChangeDetection
        && config.change_recovery == ChangeRecovery::Forget)
        .then(|| change_settings(config))
}

/// The watch and correction a learner without a tree gets under `merge_strategy
/// change_detection` with `change_recovery correct`: the `change_*` entries; none
/// otherwise.
pub fn correction_settings(config: &Config) -> Option<ChangeSettings> {
    (config.merge_strategy == MergeStrategy::ChangeDetection
        && config.change_recovery == ChangeRecovery::Correct)
        .then(|| change_settings(config))
}

/// Which pose pairs are learning patterns: `minimal_joint_move`.
pub fn pattern_settings(config: &Config) -> PatternSettings {
    PatternSettings {
        minimal_joint_move: config.minimal_joint_move,
    }
}

/// The config's boundaries of the first `N` inputs.
pub fn input_bounds<const N: usize>(config: &Config) -> [(f64, f64); N] {
    std::array::from_fn(|i| config.boundary(i))
}

/// What the nested learners share: the tree, `merge_strategy`, the `change_*` entries,
/// `minimal_joint_move` and `seed`.
fn nested_settings(config: &Config) -> NestedSettings {
    NestedSettings {
        tree: tree_settings(config),
        merge_strategy: config.merge_strategy,
        change: change_settings(config),
        patterns: pattern_settings(config),
        seed: config.seed,
    }
}

fn tree_settings(config: &Config) -> TreeSettings {
    TreeSettings {
        max_depth: config.tree_depth,
        bin_size: config.bin_size,
        max_stored_patterns: config.max_stored_patterns,
        min_pats_for_split: config.min_pats_for_split,
        split_error: config.split_error,
        am_error_tresh: config.am_error_tresh,
        am_error_iters: config.am_error_iters,
        merge_error: config.merge_error,
        monitor_ave: config.monitor_ave,
        known_pattern_perc: config.known_pattern_perc,
        retrain_limit: config.nnw_train_limit,
        retrain_delay: config.nnw_train_delay,
    }
}

fn change_settings(config: &Config) -> ChangeSettings {
    ChangeSettings {
        detector: DetectorSettings {
            baseline: config.change_baseline,
            lag: config.change_lag,
            warmup: config.change_warmup,
            drift: config.change_drift,
            threshold: config.change_threshold,
        },
        grace: config.change_grace,
        min_fresh: config.change_min_fresh,
        recovery: config.change_recovery,
        fit_patterns: config.change_fit_patterns,
        split_patterns: config.change_split_patterns,
    }
}

fn perceptron_settings(config: &Config) -> PerceptronSettings {
    PerceptronSettings {
        sum_sets: config.nr_of_matrices,
        set_size: config.max_pats_in_mat,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::experiment::setup::dynamic_settings;
    use crate::robot::DynamicSettings;

    /// Each learner's settings from the declared defaults are its `Settings::default`
    /// (which the declarations take their defaults from): every entry reaches the field it
    /// names, and a default shared by two learners (`wrange`, `norm_out`) is the same in
    /// both.
    #[test]
    fn every_settings_default_is_the_declared_defaults() {
        let config = Config::defaults();
        assert_eq!(lin5_settings(&config), Lin5Settings::default());
        assert_eq!(lin8_settings(&config), Lin8Settings::default());
        assert_eq!(nnw_settings(&config), NnwSettings::default());
        assert_eq!(ffn_settings(&config), FfnSettings::default());
        assert_eq!(kohonen_settings(&config), KohonenSettings::default());
        assert_eq!(lwpr_settings(&config), LwprSettings::default());
        assert_eq!(issgp_settings(&config), IssgpSettings::default());
        assert_eq!(mlp_settings(&config), MlpSettings::default());
        assert_eq!(broyden_settings(&config), BroydenSettings::default());
        assert_eq!(dynamic_settings(&config), DynamicSettings::default());
    }
}
