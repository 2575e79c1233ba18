//! `eyehand compare` and `eyehand sweep`: a study's cells run side by side here or written
//! as a Slurm job array (`--slurm`); `… gather DIR` tabulates a study's finished cells and
//! `… cell DIR I` runs one cell (what each local process and each Slurm task does).

use super::{bad_input, failed, say, Failure};
use crate::experiment::study::{
    check_slurm_folder, compare_plan, gather, parse_seeds, run_cell, run_locally, shell_quote,
    sweep_plan, write_slurm_script, CellLauncher, CellRunError, CompareRequest, LocalRunEnd,
    Setting, SlurmOptions, StudyError, StudyFolder, StudyKind, StudyPlan,
};
use crate::experiment::{Event, StopRequest};
use crate::learn::Method;
use std::path::PathBuf;

#[derive(Debug, clap::Args)]
#[command(args_conflicts_with_subcommands = true, subcommand_negates_reqs = true)]
pub(super) struct CompareArgs {
    #[command(subcommand)]
    action: Option<StudyAction>,
    /// The methods, comma-separated.
    #[arg(long, value_enum, value_delimiter = ',', required = true)]
    methods: Vec<Method>,
    /// Trials per run.
    #[arg(
        long,
        required = true,
        allow_negative_numbers = true,
        value_parser = super::count_at_least_1
    )]
    trials: Option<usize>,
    /// Seeds: FIRST..LAST or a list like 1,2,3.
    #[arg(long, default_value = "1,2,3")]
    seeds: String,
    /// An event of every run: rotate:TRIAL:DEG or elongate:TRIAL:LINK:CM (repeatable).
    #[arg(long = "event")]
    events: Vec<Event>,
    /// The data folder; the comparison goes to <data>/compare/<id>/.
    #[arg(long, default_value = "data")]
    data: PathBuf,
    /// Folder of per-method configs (<method>.conf; default: configs/ if it exists).
    #[arg(long)]
    configs: Option<PathBuf>,
    /// Sets any config entry of every run: NAME=VALUE (repeatable; applied after the
    /// method's config).
    #[arg(long = "set", value_name = "NAME=VALUE")]
    sets: Vec<String>,
    #[command(flatten)]
    slurm: SlurmArgs,
}

#[derive(Debug, clap::Args)]
#[command(args_conflicts_with_subcommands = true, subcommand_negates_reqs = true)]
pub(super) struct SweepArgs {
    #[command(subcommand)]
    action: Option<StudyAction>,
    /// The config every cell starts from.
    #[arg(long, required = true)]
    config: Option<PathBuf>,
    /// NAME=V1,V2,… (repeatable, each name once): the settings to cross.
    #[arg(long = "set", required = true)]
    sets: Vec<Setting>,
    /// Seeds: FIRST..LAST or a list like 1,2,3 (the only way to vary the seed).
    #[arg(long, default_value = "1")]
    seeds: String,
    /// The data folder; the sweep goes to <data>/sweep/<id>/.
    #[arg(long, default_value = "data")]
    data: PathBuf,
    #[command(flatten)]
    slurm: SlurmArgs,
}

#[derive(Debug, clap::Subcommand)]
enum StudyAction {
    /// Writes table.md and curves.png from the finished cells of a study folder and lists
    /// the others with the sbatch line that reruns them.
    Gather {
        /// The study folder (data/sweep/<id> or data/compare/<id>).
        dir: PathBuf,
    },
    /// Runs one cell of a study folder into its cells/<INDEX>/ (what each Slurm task runs).
    Cell {
        /// The study folder.
        dir: PathBuf,
        /// The cell's index.
        index: usize,
    },
}

#[derive(Debug, clap::Args)]
struct SlurmArgs {
    /// Writes the study's folder and an sbatch job-array script instead of running the cells.
    #[arg(long)]
    slurm: bool,
    /// The eyehand binary the script runs (default: this one's absolute path).
    #[arg(long, requires = "slurm")]
    slurm_binary: Option<PathBuf>,
    /// #SBATCH --time (e.g. 1:00:00).
    #[arg(long, requires = "slurm")]
    slurm_time: Option<String>,
    /// #SBATCH --mem (default: the cells' memory class, e.g. 256M).
    #[arg(long, requires = "slurm")]
    slurm_mem: Option<String>,
    /// #SBATCH --partition.
    #[arg(long, requires = "slurm")]
    slurm_partition: Option<String>,
    /// #SBATCH --account.
    #[arg(long, requires = "slurm")]
    slurm_account: Option<String>,
    /// A further #SBATCH line, e.g. '--qos=low' (repeatable).
    #[arg(
        long,
        requires = "slurm",
        value_name = "LINE",
        allow_hyphen_values = true
    )]
    slurm_extra: Vec<String>,
}

fn study_failure(e: StudyError) -> Failure {
    if e.is_bad_input() {
        bad_input(e)
    } else {
        failed(e)
    }
}

fn this_program() -> Result<PathBuf, Failure> {
    std::env::current_exe().map_err(|e| failed(format!("cannot find the eyehand binary: {e}")))
}

pub(super) fn compare(args: CompareArgs) -> Result<(), Failure> {
    if let Some(action) = args.action {
        return act(action);
    }
    let request = CompareRequest {
        methods: args.methods,
        trials: args.trials.unwrap_or(1),
        seeds: parse_seeds(&args.seeds).map_err(study_failure)?,
        events: args.events,
        sets: super::run::name_values(&args.sets)?,
        configs: args.configs,
    };
    let plan = compare_plan(&request).map_err(study_failure)?;
    carry_out(plan, &args.data, args.slurm)
}

pub(super) fn sweep(args: SweepArgs) -> Result<(), Failure> {
    if let Some(action) = args.action {
        return act(action);
    }
    let config = args.config.unwrap_or_default();
    let seeds = parse_seeds(&args.seeds).map_err(study_failure)?;
    let plan = sweep_plan(&config, &args.sets, &seeds).map_err(study_failure)?;
    carry_out(plan, &args.data, args.slurm)
}

fn act(action: StudyAction) -> Result<(), Failure> {
    match action {
        StudyAction::Gather { dir } => gather_study(&StudyFolder(dir)),
        StudyAction::Cell { dir, index } => {
            let stop =
                StopRequest::on_signals().map_err(|e| failed(format!("signal handlers: {e}")))?;
            run_one_cell(&StudyFolder(dir), index, stop)
        }
    }
}

/// Runs one cell here; exits as `eyehand run` would (130/143 when a signal stopped it).
fn run_one_cell(folder: &StudyFolder, index: usize, stop: StopRequest) -> Result<(), Failure> {
    match run_cell(folder, index, stop.clone()) {
        Ok(result) => {
            say(&format!("{}\n", result.folder.display()))?;
            match stop.exit_code() {
                Some(code) => Err((code, format!("cell {index} interrupted"))),
                None => Ok(()),
            }
        }
        Err(CellRunError::Study(e)) => Err(study_failure(e)),
        Err(CellRunError::Run(e)) if e.refused_before_work() => Err(bad_input(e)),
        Err(e) => Err(failed(e)),
    }
}

/// Creates the study's folder and job script, then runs its cells here and gathers them,
/// or (with `--slurm`) says how to submit and gather them.
fn carry_out(plan: StudyPlan, data: &std::path::Path, slurm: SlurmArgs) -> Result<(), Failure> {
    let options = SlurmOptions {
        time: slurm.slurm_time,
        mem: slurm.slurm_mem,
        partition: slurm.slurm_partition,
        account: slurm.slurm_account,
        extra: slurm.slurm_extra,
    };
    options.check().map_err(study_failure)?;
    if slurm.slurm {
        let data = std::path::absolute(data).map_err(bad_input)?;
        check_slurm_folder(&data).map_err(study_failure)?;
    }
    let binary = match slurm.slurm_binary {
        Some(path) => std::path::absolute(&path).map_err(bad_input)?,
        None => this_program()?,
    };
    let configs = plan.check().map_err(study_failure)?;
    let kind = plan.kind;
    let cells = plan.cells.len();
    let launcher = CellLauncher {
        program: binary,
        args: vec![kind.name().to_string(), "cell".to_string()],
    };
    let folder = plan.clone().create(data).map_err(study_failure)?;
    let script =
        write_slurm_script(&folder, &plan, &configs, &launcher, &options).map_err(study_failure)?;
    if slurm.slurm {
        // Quoted for a shell: the lines are meant to be pasted.
        let quoted = shell_quote(&script.display().to_string());
        let dir = shell_quote(&folder.0.display().to_string());
        say(&format!(
            "{}\nsubmit: sbatch {quoted}\ngather: eyehand {} gather {dir}\n",
            script.display(),
            kind.name()
        ))?;
        return Ok(());
    }
    let local = CellLauncher {
        program: this_program()?,
        ..launcher
    };
    let jobs = std::thread::available_parallelism().map_or(1, |n| n.get());
    let end = run_locally(&folder, cells, &local, jobs).map_err(study_failure)?;
    let gathered = gather_study(&folder);
    match end {
        LocalRunEnd::Completed => gathered,
        LocalRunEnd::Interrupted(signal) => Err((
            128 + signal as u8,
            format!("{} interrupted by signal {signal}", kind_name(kind)),
        )),
    }
}

fn kind_name(kind: StudyKind) -> &'static str {
    match kind {
        StudyKind::Compare => "the comparison",
        StudyKind::Sweep => "the sweep",
    }
}

/// Gathers a study and prints its folder, table and unfinished cells.
fn gather_study(folder: &StudyFolder) -> Result<(), Failure> {
    let report = gather(folder).map_err(study_failure)?;
    say(&format!("{}\n{}", report.folder.display(), report.table))?;
    if report.unfinished.is_empty() {
        return Ok(());
    }
    let total = report.finished.len() + report.unfinished.len();
    let missing = report.unfinished.len();
    let mut text = format!("\n{missing} of {total} cells did not finish:\n");
    for cell in &report.unfinished {
        text += &format!(
            "  cell {} ({}, seed {}): {}\n",
            cell.index, cell.label, cell.seed, cell.reason
        );
        if let Some(log) = &cell.log {
            text += &format!("    {}:\n", log.display());
            for line in &cell.log_tail {
                text += &format!("    | {line}\n");
            }
        }
    }
    if let Some(line) = &report.resubmit {
        text += &format!("rerun them: {line}\n");
    }
    say(&text)?;
    Err(failed(format!("{missing} of {total} cells did not finish")))
}
