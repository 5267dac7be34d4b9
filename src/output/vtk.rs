//! Legacy-VTK particle frames (POLYDATA with one vertex per sphere) that ParaView
//! opens directly; render them with the Glyph filter scaled by `radius`.

use crate::error::{Result, TampError};
use crate::simulation::Simulation;
use vtkio::model::{
    Attribute, Attributes, ByteOrder, DataSet, Piece, PolyDataPiece, Version, VertexNumbers, Vtk,
};

pub fn frame(sim: &Simulation) -> Vtk {
    let p = &sim.particles;
    let n = p.len();
    let flat = |v: &Vec<crate::particles::Vec3>| {
        v.iter().flat_map(|x| [x.x, x.y, x.z]).collect::<Vec<f64>>()
    };
    let vertices: Vec<u32> = (0..n as u32).flat_map(|i| [1, i]).collect();
    let data = Attributes {
        point: vec![
            Attribute::scalars("id", 1)
                .with_data(p.id.iter().map(|&k| k as f64).collect::<Vec<f64>>()),
            Attribute::scalars("radius", 1).with_data(p.radius.clone()),
            Attribute::scalars("material", 1)
                .with_data(p.material.iter().map(|&m| m as f64).collect::<Vec<f64>>()),
            Attribute::vectors("velocity").with_data(flat(&p.velocity)),
            Attribute::vectors("omega").with_data(flat(&p.omega)),
        ],
        cell: Vec::new(),
    };
    Vtk {
        version: Version::new((2, 0)),
        title: format!("tamp frame step {} time {:e}", sim.step, sim.time),
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

pub fn to_ascii(sim: &Simulation) -> Result<String> {
    let mut s = String::new();
    frame(sim)
        .write_legacy_ascii(&mut s)
        .map_err(|e| TampError::Other(format!("writing VTK frame: {e}")))?;
    Ok(s)
}

/// Delete `frame_*.vtk` left in `dir` by an earlier run, so a directory never mixes runs.
pub fn remove_frames(dir: &std::path::Path) -> Result<()> {
    let entries = std::fs::read_dir(dir)
        .map_err(|e| TampError::io(format!("reading {}", dir.display()), e))?;
    for entry in entries.flatten() {
        let name = entry.file_name().to_string_lossy().to_string();
        if name.starts_with("frame_") && name.ends_with(".vtk") {
            std::fs::remove_file(entry.path())
                .map_err(|e| TampError::io(format!("removing {name}"), e))?;
        }
    }
    Ok(())
}
