//! `eyehand compare` and `eyehand sweep`: many runs side by side.

use super::{bad_input, failed, Failure};
use crate::experiment::{
    allocate_run_folder, parse_seeds, run_cells, run_compare, slurm_script, sweep_cells,
    sweep_table, CompareRequest, Event, Setting,
};
use crate::learn::Method;
use std::path::PathBuf;

#[derive(Debug, clap::Args)]
pub(super) struct CompareArgs {
    /// The methods, comma-separated (lin5,lin8,nnw,ffn,kohonen,ik).
    #[arg(long, value_delimiter = ',', required = true)]
    methods: Vec<Method>,
    /// Trials per run.
    #[arg(long)]
    trials: usize,
    /// Seeds: FIRST..LAST or a list like 1,2,3.
    #[arg(long, default_value = "1,2,3")]
    seeds: String,
    /// An event of every run: rotate:TRIAL:DEG or elongate:TRIAL:LINK:CM (repeatable).
    #[arg(long = "event")]
    events: Vec<Event>,
    /// The data folder.
    #[arg(long, default_value = "data")]
    data: PathBuf,
    /// Folder of per-method configs (<method>.conf); others run the default config.
    #[arg(long, default_value = "configs")]
    configs: PathBuf,
}

#[derive(Debug, clap::Args)]
pub(super) struct SweepArgs {
    /// The config every cell starts from.
    #[arg(long)]
    config: PathBuf,
    /// NAME=V1,V2,… (repeatable): the settings to cross.
    #[arg(long = "set", required = true)]
    sets: Vec<Setting>,
    /// Seeds: FIRST..LAST or a list like 1,2,3.
    #[arg(long, default_value = "1")]
    seeds: String,
    /// The data folder.
    #[arg(long, default_value = "data")]
    data: PathBuf,
    /// Writes an sbatch job-array script instead of running the cells.
    #[arg(long)]
    slurm: bool,
}

fn this_program() -> Result<PathBuf, Failure> {
    std::env::current_exe().map_err(|e| failed(format!("cannot find the eyehand binary: {e}")))
}

pub(super) fn compare(args: CompareArgs) -> Result<(), Failure> {
    if args.trials == 0 {
        return Err(bad_input("--trials must be at least 1"));
    }
    let request = CompareRequest {
        methods: args.methods,
        trials: args.trials,
        seeds: parse_seeds(&args.seeds).map_err(bad_input)?,
        events: args.events,
        data: args.data,
        configs: args.configs,
    };
    let report = run_compare(&this_program()?, &request).map_err(failed)?;
    println!("{}", report.folder.display());
    print!("{}", report.table);
    Ok(())
}

pub(super) fn sweep(args: SweepArgs) -> Result<(), Failure> {
    let seeds = parse_seeds(&args.seeds).map_err(bad_input)?;
    let cells = sweep_cells(&args.config, &args.sets, &seeds, &args.data).map_err(bad_input)?;
    let folder = allocate_run_folder(&args.data, "sweep").map_err(failed)?;
    if args.slurm {
        let script = folder.join("sweep.sbatch");
        std::fs::write(&script, slurm_script(&cells, "eyehand")).map_err(failed)?;
        println!("{}", script.display());
        return Ok(());
    }
    let runs = run_cells(&this_program()?, &cells)
        .into_iter()
        .collect::<Result<Vec<_>, _>>()
        .map_err(failed)?;
    let table = sweep_table(&runs);
    std::fs::write(folder.join("table.md"), &table).map_err(failed)?;
    println!("{}", folder.display());
    print!("{table}");
    Ok(())
}
