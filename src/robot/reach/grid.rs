//! The (r, z) cells a reach-space fit looks at: which ones the arm reaches, counted fast
//! over any box of them.

use super::fit::Samples;
use crate::robot::ReachSpace;

/// The most one side of a box of other proportions than the study's may be, as a multiple
/// of the other.
const MAX_ASPECT: f64 = 4.0;

/// How far (m) a box's side stays inside its cells' edge, so that rounding never puts it
/// on the next cell.
const ROUNDING: f64 = 1e-9;
/// Grid cell of the reached (r, z) set (m).
pub(super) const CELL: f64 = 0.01;

/// The reached (r, z) cells: `rows` of `cols`, row 0 at `z0`, column 0 at r = 0.
pub(super) struct Grid {
    pub(super) z0: f64,
    pub(super) rows: usize,
    pub(super) cols: usize,
    /// Prefix sums of reached cells: `sums[(row) * (cols + 1) + col]` counts rows < row,
    /// cols < col.
    sums: Vec<u32>,
    pub(super) reached: usize,
}

impl Grid {
    /// The cells the sampled poses reach: each cell holding a sample, and each cell whose
    /// centre lies in a triangle of neighbouring samples (the reached set between them).
    pub(super) fn new(samples: &Samples) -> Option<Grid> {
        let points = || samples.centres.iter().flatten().map(|c| c.point);
        let z_low = points().map(|p| p.1).fold(f64::INFINITY, f64::min);
        let z_high = points().map(|p| p.1).fold(f64::NEG_INFINITY, f64::max);
        let r_high = points().map(|p| p.0).fold(0.0, f64::max);
        if !(z_low.is_finite() && z_high.is_finite()) {
            return None;
        }
        let rows = ((z_high - z_low) / CELL) as usize + 1;
        let cols = (r_high / CELL) as usize + 1;
        let mut hit = vec![false; rows * cols];
        let cell = |(r, z): (f64, f64)| ((z - z_low) / CELL) as usize * cols + (r / CELL) as usize;
        for point in points() {
            hit[cell(point)] = true;
        }
        for triangle in samples.triangles() {
            fill(&mut hit, (z_low, cols), &triangle);
        }
        Some(Grid::of_cells(z_low, cols, &hit))
    }

    /// The grid of `hit` (rows of `cols` cells, whether each is reached), row 0 at `z0`.
    fn of_cells(z0: f64, cols: usize, hit: &[bool]) -> Grid {
        let rows = hit.len() / cols;
        let mut sums = vec![0u32; (rows + 1) * (cols + 1)];
        for row in 0..rows {
            for col in 0..cols {
                let at = |r: usize, c: usize| sums[r * (cols + 1) + c];
                sums[(row + 1) * (cols + 1) + col + 1] = at(row, col + 1) + at(row + 1, col)
                    - at(row, col)
                    + u32::from(hit[row * cols + col]);
            }
        }
        let reached = hit.iter().filter(|h| **h).count();
        Grid {
            z0,
            rows,
            cols,
            sums,
            reached,
        }
    }

    /// Reached cells in rows `r0..r1`, columns `c0..c1`.
    pub(super) fn count(&self, (r0, r1): (usize, usize), (c0, c1): (usize, usize)) -> u32 {
        let at = |r: usize, c: usize| self.sums[r * (self.cols + 1) + c];
        at(r1, c1) + at(r0, c0) - at(r0, c1) - at(r1, c0)
    }

    /// True when every cell meeting the box r_min..r_max, z_min..z_max is reached.
    pub(super) fn covers(&self, r: (f64, f64), z: (f64, f64)) -> bool {
        let col = |v: f64| (v / CELL).floor();
        let row = |v: f64| ((v - self.z0) / CELL).floor();
        let (c0, c1, r0, r1) = (col(r.0), col(r.1) + 1.0, row(z.0), row(z.1) + 1.0);
        if c0 < 0.0 || r0 < 0.0 || c1 > self.cols as f64 || r1 > self.rows as f64 {
            return false;
        }
        let (c0, c1, r0, r1) = (c0 as usize, c1 as usize, r0 as usize, r1 as usize);
        self.count((r0, r1), (c0, c1)) as usize == (r1 - r0) * (c1 - c0)
    }

    /// The largest half annulus (by its area in r, z) whose (r, z) box, `margin` wider on
    /// every side, holds only reached cells: its lowest height at least `lowest` (m) plus
    /// `margin`, neither side more than [`MAX_ASPECT`] times the other (a longer run of
    /// cells is cut to its middle), its area at least `min_area` (m²).
    pub(super) fn largest_box(
        &self,
        lowest: f64,
        margin: f64,
        min_area: f64,
    ) -> Option<ReachSpace> {
        let first = ((lowest - self.z0) / CELL).ceil().max(0.0) as usize;
        let inset = margin + ROUNDING;
        let mut best: Option<(f64, ReachSpace)> = None;
        for bottom in first..self.rows {
            for top in bottom + 1..=self.rows {
                let full =
                    |col: usize| self.count((bottom, top), (col, col + 1)) as usize == top - bottom;
                let runs = self.runs(full);
                if runs.is_empty() {
                    break;
                }
                let height = (top - bottom) as f64 * CELL - 2.0 * inset;
                for (start, end) in runs {
                    let run = (end - start) as f64 * CELL - 2.0 * inset;
                    let width = run.min(MAX_ASPECT * height);
                    let area = width * height;
                    if height <= 0.0
                        || height > MAX_ASPECT * (width + 2.0 * ROUNDING)
                        || area < min_area
                    {
                        continue;
                    }
                    if best.as_ref().is_none_or(|(top_area, _)| area > *top_area) {
                        let r_min = start as f64 * CELL + inset + 0.5 * (run - width);
                        let z_min = self.z0 + bottom as f64 * CELL + inset;
                        let space = ReachSpace {
                            r_min,
                            r_max: r_min + width,
                            z_min,
                            z_max: z_min + height,
                        };
                        best = Some((area, space));
                    }
                }
            }
        }
        best.map(|(_, space)| space)
    }

    /// The runs of neighbouring columns (first, one past the last) for which `full` holds.
    fn runs(&self, full: impl Fn(usize) -> bool) -> Vec<(usize, usize)> {
        let mut runs = Vec::new();
        let mut start = None;
        for col in 0..=self.cols {
            match (start, col < self.cols && full(col)) {
                (None, true) => start = Some(col),
                (Some(first), false) => {
                    runs.push((first, col));
                    start = None;
                }
                _ => {}
            }
        }
        runs
    }
}

/// Marks in `hit` (rows of `cols` cells, row 0 at `z0`) each cell whose centre lies in
/// `triangle` (r, z).
pub(super) fn fill(hit: &mut [bool], (z0, cols): (f64, usize), triangle: &[(f64, f64); 3]) {
    let [a, b, c] = *triangle;
    let cross = |p: (f64, f64), q: (f64, f64), x: (f64, f64)| {
        (q.0 - p.0) * (x.1 - p.1) - (q.1 - p.1) * (x.0 - p.0)
    };
    let area = cross(a, b, c);
    if area == 0.0 {
        return;
    }
    let extreme = |f: fn(f64, f64) -> f64, pick: fn(&(f64, f64)) -> f64| {
        triangle.iter().map(pick).fold(pick(&a), f)
    };
    let (r0, r1) = (extreme(f64::min, |p| p.0), extreme(f64::max, |p| p.0));
    let (z_lo, z_hi) = (extreme(f64::min, |p| p.1), extreme(f64::max, |p| p.1));
    let rows = hit.len() / cols;
    let first = |v: f64| ((v / CELL - 0.5).ceil().max(0.0)) as usize;
    let last = |v: f64, n: usize| ((v / CELL - 0.5).floor() as usize).min(n - 1);
    for row in first(z_lo - z0)..=last(z_hi - z0, rows) {
        for col in first(r0)..=last(r1, cols) {
            let x = ((col as f64 + 0.5) * CELL, z0 + (row as f64 + 0.5) * CELL);
            let signs = [cross(a, b, x), cross(b, c, x), cross(c, a, x)];
            if signs.iter().all(|s| s * area >= 0.0) {
                hit[row * cols + col] = true;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An L of reached cells from z = 0 up: a wide, low foot (r 10..70 cm, z 0..8 cm) and
    /// a narrow, tall column (r 10..22 cm, z 0..80 cm).
    fn foot_and_column() -> Grid {
        let (rows, cols) = (80, 80);
        let hit: Vec<bool> = (0..rows * cols)
            .map(|cell| {
                let (row, col) = (cell / cols, cell % cols);
                (10..70).contains(&col) && row < 8 || (10..22).contains(&col) && row < 80
            })
            .collect();
        Grid::of_cells(0.0, cols, &hit)
    }

    #[test]
    fn the_largest_box_keeps_its_margin_inside_the_reached_cells() {
        let grid = foot_and_column();
        let space = grid.largest_box(0.0, 0.02, 0.0).unwrap();
        // The column (8 cm wide inside its margin, cut to four times that in height) is
        // larger than the foot (4 cm high, cut to 16 cm wide).
        let near = |a: f64, b: f64| (a - b).abs() < 1e-6;
        assert!(
            near(space.r_min, 0.12) && near(space.r_max, 0.20),
            "{space:?}"
        );
        assert!(near(space.z_max - space.z_min, 0.32), "{space:?}");
        assert!(grid.covers(
            (space.r_min - 0.02, space.r_max + 0.02),
            (space.z_min - 0.02, space.z_max + 0.02)
        ));
        // Above the foot, only the column is left; a floor above it leaves nothing.
        let above = grid.largest_box(0.2, 0.02, 0.0).unwrap();
        assert!(near(above.r_min, 0.12) && above.z_min >= 0.22, "{above:?}");
        assert_eq!(grid.largest_box(0.9, 0.02, 0.0), None);
        // No box as large as asked.
        assert_eq!(grid.largest_box(0.0, 0.02, 0.05), None);
    }
}
