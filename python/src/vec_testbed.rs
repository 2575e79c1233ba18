//! `eyehand._eyehand.VecTestbed`: N arms of `eyehand/Reach-v0` stepped in one call, on
//! worker threads when asked to (the engine behind `eyehand.vector.ReachVectorEnv`).

use crate::arm::{ArmReport, ArmRules, EndCode, OBS_LEN};
use crate::pool::{ArmPool, PoolError};
use crate::testbed::run_setup;
use numpy::{PyArray1, PyArray2, PyArrayMethods, PyReadonlyArray2};
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::path::PathBuf;

/// What a reset or a step returns: observations (N, 5) float32, rewards, terminated,
/// truncated, end codes (0 going on, 1 reached, 2 steps used, 3 lost), distances (mm),
/// joints (N, 3, degrees), seen, camera positions and goal points (N, 3, world, mm).
type Batch<'py> = (
    Bound<'py, PyArray2<f32>>,
    Bound<'py, PyArray1<f64>>,
    Bound<'py, PyArray1<bool>>,
    Bound<'py, PyArray1<bool>>,
    Bound<'py, PyArray1<u8>>,
    Bound<'py, PyArray1<f64>>,
    Bound<'py, PyArray2<f64>>,
    Bound<'py, PyArray1<bool>>,
    Bound<'py, PyArray2<f64>>,
    Bound<'py, PyArray2<f64>>,
);

/// `VecTestbed(num_envs, max_move_deg, obs_low, obs_high, lost_reward, config=None,
/// sim="kinematic", camera="projection", seed=1, urdf=None, threads=1, **entries)`: arm i a
/// testbed of seed `seed + i`, the arms split among `threads` threads.
#[pyclass(unsendable, module = "eyehand")]
#[derive(Debug)]
pub struct VecTestbed {
    pool: ArmPool,
}

#[pymethods]
impl VecTestbed {
    #[new]
    #[pyo3(signature = (num_envs, max_move_deg, obs_low, obs_high, lost_reward, config = None, sim = "kinematic", camera = "projection", seed = 1, urdf = None, threads = 1, **entries))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        num_envs: usize,
        max_move_deg: [f64; 3],
        obs_low: [f32; OBS_LEN],
        obs_high: [f32; OBS_LEN],
        lost_reward: f64,
        config: Option<PathBuf>,
        sim: &str,
        camera: &str,
        seed: u64,
        urdf: Option<PathBuf>,
        threads: usize,
        entries: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<VecTestbed> {
        if num_envs == 0 {
            return Err(PyValueError::new_err("num_envs must be at least 1"));
        }
        if !max_move_deg.iter().all(|m| m.is_finite() && *m > 0.0) {
            return Err(PyValueError::new_err(format!(
                "max_move_deg must be positive and finite, not {max_move_deg:?}"
            )));
        }
        let setup = run_setup(config, sim, camera, seed, urdf, entries)?;
        let rules = ArmRules {
            max_move_deg,
            obs_low,
            obs_high,
            lost_reward,
        };
        Ok(VecTestbed {
            pool: ArmPool::new(&setup, seed, num_envs, threads, rules),
        })
    }

    /// Resets the arms `mask` picks (arm i from `seeds[i]` when it is not None) and returns
    /// every arm's latest report (an arm not reset keeps its last one).
    fn reset<'py>(
        &mut self,
        py: Python<'py>,
        seeds: Vec<Option<u64>>,
        mask: Vec<bool>,
    ) -> PyResult<Batch<'py>> {
        let n = self.pool.len();
        if seeds.len() != n || mask.len() != n {
            return Err(PyValueError::new_err(format!(
                "{n} seeds and a mask of {n} are needed, not {} and {}",
                seeds.len(),
                mask.len()
            )));
        }
        self.pool.reset(&seeds, &mask).map_err(pool_error)?;
        self.batch(py)
    }

    /// Steps every arm with its row of `actions` (N, 3): shares of the move bound, clipped
    /// to ±1; an arm whose episode ended at the last step is reset instead.
    fn step<'py>(
        &mut self,
        py: Python<'py>,
        actions: PyReadonlyArray2<'py, f32>,
    ) -> PyResult<Batch<'py>> {
        let n = self.pool.len();
        let shape = actions.as_array().dim();
        if shape != (n, 3) {
            return Err(PyValueError::new_err(format!(
                "actions must be of shape ({n}, 3), not {shape:?}"
            )));
        }
        let copied: Vec<f32>;
        let flat = match actions.as_slice() {
            Ok(flat) => flat,
            Err(_) => {
                copied = actions.as_array().iter().copied().collect();
                &copied
            }
        };
        if !flat.iter().all(|a| a.is_finite()) {
            return Err(PyValueError::new_err("actions must be finite"));
        }
        self.pool.step(flat).map_err(pool_error)?;
        self.batch(py)
    }

    /// How many arms there are.
    fn __len__(&self) -> usize {
        self.pool.len()
    }
}

impl VecTestbed {
    /// Every arm's latest report as NumPy columns.
    fn batch<'py>(&self, py: Python<'py>) -> PyResult<Batch<'py>> {
        let n = self.pool.len();
        let reports: Vec<&ArmReport> = self.pool.reports().collect();
        let column =
            |f: &dyn Fn(&ArmReport) -> f64| -> Vec<f64> { reports.iter().map(|r| f(r)).collect() };
        let triple = |f: &dyn Fn(&ArmReport) -> [f64; 3]| {
            let flat: Vec<f64> = reports.iter().flat_map(|r| f(r)).collect();
            matrix(py, flat, n, 3)
        };
        let flags = |f: &dyn Fn(&ArmReport) -> bool| {
            let flat: Vec<bool> = reports.iter().map(|r| f(r)).collect();
            PyArray1::from_vec(py, flat)
        };
        let obs: Vec<f32> = reports.iter().flat_map(|r| r.obs).collect();
        let ends: Vec<u8> = reports.iter().map(|r| r.end as u8).collect();
        Ok((
            matrix(py, obs, n, OBS_LEN)?,
            PyArray1::from_vec(py, column(&|r| r.reward)),
            flags(&|r| r.end == EndCode::Reached),
            flags(&|r| matches!(r.end, EndCode::StepsUsed | EndCode::Lost)),
            PyArray1::from_vec(py, ends),
            PyArray1::from_vec(py, column(&|r| r.distance_mm)),
            triple(&|r| r.joints_deg)?,
            flags(&|r| r.seen),
            triple(&|r| r.camera_mm)?,
            triple(&|r| r.goal_mm)?,
        ))
    }
}

/// A flat row-major vector as an (rows, columns) array.
fn matrix<T: numpy::Element>(
    py: Python<'_>,
    flat: Vec<T>,
    rows: usize,
    columns: usize,
) -> PyResult<Bound<'_, PyArray2<T>>> {
    PyArray1::from_vec(py, flat).reshape([rows, columns])
}

/// A failed reset or step: bad actions as `ValueError`, the rest as `RuntimeError`.
fn pool_error(error: PoolError) -> PyErr {
    match error {
        PoolError::Arm {
            failure: eyehand::control::Failure::NonFiniteMove,
            ..
        } => PyValueError::new_err(error.to_string()),
        _ => PyRuntimeError::new_err(error.to_string()),
    }
}
