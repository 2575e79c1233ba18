//! The physical ranges a robot description's numbers must lie in: no link, offset or shape
//! longer than [`MAX_LENGTH_M`], no link heavier than [`MAX_MASS_KG`], no mesh scaled by a
//! factor outside [`MESH_SCALE`] or smaller than [`MIN_SIZE_M`]. A URDF beyond them is
//! refused where it is read, so every command that reads it refuses it alike.

use super::DescriptionErrorKind as Kind;

/// The longest offset of a joint or link origin, shape side or mesh point from its frame
/// (m): a robot arm is not 100 m long.
pub const MAX_LENGTH_M: f64 = 100.0;
/// The smallest shape size or mesh extent (m): 1 µm.
pub const MIN_SIZE_M: f64 = 1e-6;
/// The heaviest link (kg): 100 t.
pub const MAX_MASS_KG: f64 = 1e5;
/// The smallest and largest size of a mesh's scale factor.
pub const MESH_SCALE: (f64, f64) = (1e-6, 1e6);

/// A number as a message shows it: plainly, or in exponent form when that is long.
pub(super) fn number(value: f64) -> String {
    let plain = value.to_string();
    if plain.len() > 16 {
        format!("{value:e}")
    } else {
        plain
    }
}

/// `value` and its unit, as a message shows them.
pub(super) fn with_unit(value: f64, unit: &str) -> String {
    match unit {
        "" => number(value),
        unit => format!("{} {unit}", number(value)),
    }
}

/// The range of sizes from `low` (0: none) to `high`, in words.
pub(super) fn range_text(low: f64, high: f64, unit: &str) -> String {
    if low == 0.0 {
        format!("a size of at most {}", with_unit(high, unit))
    } else {
        format!("a size from {} to {}", number(low), with_unit(high, unit))
    }
}

/// An error unless every value's size is at most `high` (and at least `low` when it is not
/// 0); `element` and `what` name them, `unit` is theirs.
pub(super) fn within(
    values: &[f64],
    (low, high): (f64, f64),
    element: &str,
    unit: &'static str,
) -> Result<(), Kind> {
    match values
        .iter()
        .find(|v| !(v.abs() <= high && (low == 0.0 || v.abs() >= low)))
    {
        Some(&value) => Err(Kind::OutOfPhysicalRange {
            element: element.to_string(),
            value,
            low,
            high,
            unit,
        }),
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_beyond_the_ranges_are_named_short() {
        assert!(within(&[0.6, -0.3], (0.0, MAX_LENGTH_M), "joint `j` origin", "m").is_ok());
        let error = within(&[0.6, 1e300], (0.0, MAX_LENGTH_M), "joint `j` origin", "m")
            .unwrap_err()
            .to_string();
        assert_eq!(
            error,
            "joint `j` origin: 1e300 m is outside the physical range (a size of at most 100 m)"
        );
        let error = within(&[1e-31], MESH_SCALE, "link `l` mesh `m.obj` scale", "")
            .unwrap_err()
            .to_string();
        assert_eq!(
            error,
            "link `l` mesh `m.obj` scale: 1e-31 is outside the physical range (a size from 0.000001 to 1000000)"
        );
        assert_eq!(number(0.25), "0.25");
    }
}
