//! Legacy-VTK particle frames (POLYDATA with one vertex per sphere) that ParaView
//! opens directly; render them with the Glyph filter scaled by `radius`.

use crate::error::{Result, TampError};
use crate::simulation::Simulation;
use vtkio::model::{
    Attribute, Attributes, ByteOrder, DataSet, Piece, PolyDataPiece, Version, VertexNumbers, Vtk,
};

/// `forces`: add each particle's force and torque as point data (`output.forces`).
pub fn frame(sim: &Simulation, forces: bool) -> Vtk {
    let p = &sim.state.particles;
    let n = p.len();
    let flat = |v: &Vec<crate::particles::Vec3>| {
        v.iter().flat_map(|x| [x.x, x.y, x.z]).collect::<Vec<f64>>()
    };
    let vertices: Vec<u32> = (0..n as u32).flat_map(|i| [1, i]).collect();
    let mut point = vec![
        Attribute::scalars("id", 1).with_data(p.id.iter().map(|&k| k as f64).collect::<Vec<f64>>()),
        Attribute::scalars("radius", 1).with_data(p.radius.clone()),
        Attribute::scalars("material", 1)
            .with_data(p.material.iter().map(|&m| m as f64).collect::<Vec<f64>>()),
        Attribute::vectors("velocity").with_data(flat(&p.velocity)),
        Attribute::vectors("omega").with_data(flat(&p.omega)),
    ];
    if forces {
        point.push(Attribute::vectors("force").with_data(flat(&p.force)));
        point.push(Attribute::vectors("torque").with_data(flat(&p.torque)));
    }
    let data = Attributes {
        point,
        cell: Vec::new(),
    };
    Vtk {
        version: Version::new((2, 0)),
        title: format!(
            "tamp frame step {} time {:e}",
            sim.state.step, sim.state.time
        ),
        byte_order: ByteOrder::BigEndian,
        file_path: None,
        data: DataSet::PolyData {
            meta: None,
            pieces: vec![Piece::Inline(Box::new(PolyDataPiece {
                points: flat(&p.position).into(),
                verts: Some(VertexNumbers::Legacy {
                    num_cells: n as u32,
                    vertices,
                }),
                lines: None,
                polys: None,
                strips: None,
                data,
            }))],
        },
    }
}

/// One particle frame as legacy-VTK ASCII text (see [`frame`]).
pub fn to_ascii(sim: &Simulation, forces: bool) -> Result<String> {
    let mut s = String::new();
    frame(sim, forces)
        .write_legacy_ascii(&mut s)
        .map_err(|e| TampError::Other(format!("writing VTK frame: {e}")))?;
    Ok(s)
}

/// Delete `frame_*.vtk` left in `dir` by an earlier run, so a directory never mixes runs.
pub fn remove_frames(dir: &std::path::Path) -> Result<()> {
    remove_numbered(dir, "frame_", &[".vtk"])
}

/// Delete the files `prefix*` with one of the extensions `ext` in `dir`.
pub fn remove_numbered(dir: &std::path::Path, prefix: &str, ext: &[&str]) -> Result<()> {
    let entries = std::fs::read_dir(dir)
        .map_err(|e| TampError::io(format!("reading {}", dir.display()), e))?;
    for entry in entries.flatten() {
        let name = entry.file_name().to_string_lossy().to_string();
        if name.starts_with(prefix) && ext.iter().any(|e| name.ends_with(e)) {
            std::fs::remove_file(entry.path())
                .map_err(|e| TampError::io(format!("removing {name}"), e))?;
        }
    }
    Ok(())
}
