//! Numbers as the page reads them: poses as `[x, y, z, qx, qy, qz, qw]` (m) and arrays of
//! numbers as base64 of their little-endian bytes.

use base64::engine::general_purpose::STANDARD;
use base64::Engine;
use nalgebra::Isometry3;

/// A pose as `[x, y, z, qx, qy, qz, qw]`, single precision (a micrometre is far below a
/// pixel).
pub(super) fn pose_json(pose: &Isometry3<f64>) -> [f32; 7] {
    let t = pose.translation.vector;
    let q = pose.rotation.coords;
    [t.x, t.y, t.z, q.x, q.y, q.z, q.w].map(|v| v as f32)
}

/// `values` as base64 of their little-endian bytes (a JavaScript `Float32Array`).
pub(super) fn base64_f32(values: &[f32]) -> String {
    let bytes: Vec<u8> = values.iter().flat_map(|v| v.to_le_bytes()).collect();
    STANDARD.encode(bytes)
}

/// `values` as base64 of their little-endian bytes (a JavaScript `Uint32Array`).
pub(super) fn base64_u32(values: &[u32]) -> String {
    let bytes: Vec<u8> = values.iter().flat_map(|v| v.to_le_bytes()).collect();
    STANDARD.encode(bytes)
}

/// `bytes` as a `data:` URL of a PNG image.
pub(super) fn png_data_url(bytes: &[u8]) -> String {
    format!("data:image/png;base64,{}", STANDARD.encode(bytes))
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Translation3, UnitQuaternion, Vector3};

    #[test]
    fn poses_and_arrays_are_written_as_the_page_reads_them() {
        let turn = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), std::f64::consts::PI);
        let pose = Isometry3::from_parts(Translation3::new(0.5, -0.25, 1.0), turn);
        let [x, y, z, qx, qy, qz, qw] = pose_json(&pose);
        assert_eq!((x, y, z), (0.5, -0.25, 1.0));
        assert!(
            qx.abs() < 1e-7 && qy.abs() < 1e-7 && (qz.abs() - 1.0).abs() < 1e-7 && qw.abs() < 1e-7
        );
        assert_eq!(base64_f32(&[1.0]), "AACAPw==");
        assert_eq!(base64_u32(&[1, 256]), "AQAAAAABAAA=");
        assert!(png_data_url(&[0x89]).starts_with("data:image/png;base64,iQ=="));
    }
}
