//! The contact network of one step (`output.contacts_every`): `contacts/contacts_NNNNNN.csv`
//! and `contacts/contacts_NNNNNN.vtk`, NNNNNN = step / contacts_every. In the VTK file each
//! contact is a line from particle i's centre to its partner's centre (or to the wall's
//! contact point), with the forces as cell data, so ParaView's Tube filter scaled by
//! `normal_force` draws the force chains.

use super::Sci;
use crate::contact::record::{ContactRecord, Partner};
use crate::error::{Result, TampError};
use crate::simulation::Simulation;
use std::fmt::Write;
use vtkio::model::{
    Attribute, Attributes, ByteOrder, DataSet, Piece, PolyDataPiece, Version, VertexNumbers, Vtk,
};

/// Header of the contacts CSV: step, particle id i, the partner (particle id j or wall
/// name), the contact point (m), the unit normal from the partner towards i, the normal
/// force on i (N), the tangential force on i (N) and the overlap δ (m).
pub const CONTACTS_HEADER: &str = "step,i,j,wall,x,y,z,nx,ny,nz,normal_force,tx,ty,tz,overlap";

/// One row per contact; `i` and `j` are particle ids (as in trajectory.csv). A pair
/// has both and an empty `wall`; a wall contact has an empty `j` and the wall's name
/// in `wall`.
pub fn to_csv(sim: &Simulation, records: &[ContactRecord]) -> String {
    let mut out = String::from(CONTACTS_HEADER);
    out.push('\n');
    for r in records {
        let (j, wall) = match r.partner {
            Partner::Particle(j) => (sim.state.particles.id[j].to_string(), ""),
            Partner::Wall(w) => (String::new(), sim.model.walls[w].name.as_str()),
        };
        let (x, n, t) = (r.point, r.normal, r.tangential_force);
        let _ = writeln!(
            out,
            "{},{},{j},{wall},{},{},{},{},{},{},{},{},{},{},{}",
            sim.state.step,
            sim.state.particles.id[r.i],
            Sci(x.x),
            Sci(x.y),
            Sci(x.z),
            Sci(n.x),
            Sci(n.y),
            Sci(n.z),
            Sci(r.normal_force),
            Sci(t.x),
            Sci(t.y),
            Sci(t.z),
            Sci(r.overlap)
        );
    }
    out
}

/// Legacy-VTK POLYDATA: two points and one line per contact; cell data
/// `normal_force`, `tangential_force` (vector), `overlap` and `wall` (−1 for a pair,
/// else the wall's index).
pub fn to_vtk(sim: &Simulation, records: &[ContactRecord]) -> Result<String> {
    let n = records.len();
    let points: Vec<f64> = records
        .iter()
        .flat_map(|r| [r.centre, r.other_end])
        .flat_map(|x| [x.x, x.y, x.z])
        .collect();
    let vertices: Vec<u32> = (0..n as u32).flat_map(|k| [2, 2 * k, 2 * k + 1]).collect();
    let data = Attributes {
        point: Vec::new(),
        cell: vec![
            Attribute::scalars("normal_force", 1)
                .with_data(records.iter().map(|r| r.normal_force).collect::<Vec<f64>>()),
            Attribute::vectors("tangential_force").with_data(
                records
                    .iter()
                    .flat_map(|r| {
                        [
                            r.tangential_force.x,
                            r.tangential_force.y,
                            r.tangential_force.z,
                        ]
                    })
                    .collect::<Vec<f64>>(),
            ),
            Attribute::scalars("overlap", 1)
                .with_data(records.iter().map(|r| r.overlap).collect::<Vec<f64>>()),
            Attribute::scalars("wall", 1).with_data(
                records
                    .iter()
                    .map(|r| match r.partner {
                        Partner::Particle(_) => -1.0,
                        Partner::Wall(w) => w as f64,
                    })
                    .collect::<Vec<f64>>(),
            ),
        ],
    };
    let vtk = Vtk {
        version: Version::new((2, 0)),
        title: format!(
            "tamp contacts step {} time {:e}",
            sim.state.step, sim.state.time
        ),
        byte_order: ByteOrder::BigEndian,
        file_path: None,
        data: DataSet::PolyData {
            meta: None,
            pieces: vec![Piece::Inline(Box::new(PolyDataPiece {
                points: points.into(),
                verts: None,
                lines: Some(VertexNumbers::Legacy {
                    num_cells: n as u32,
                    vertices,
                }),
                polys: None,
                strips: None,
                data,
            }))],
        },
    };
    let mut s = String::new();
    vtk.write_legacy_ascii(&mut s)
        .map_err(|e| TampError::Other(format!("writing VTK contacts: {e}")))?;
    Ok(s)
}
