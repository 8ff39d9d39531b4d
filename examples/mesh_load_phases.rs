//! Where the time of `kreisel inertia FILE` goes, phase by phase, in ns per
//! triangle of CPU time (this thread's, from `/proc/thread-self/schedstat`,
//! so waiting for a core on a busy machine is not counted; wall clock where
//! that file does not exist). From 32768 triangles the phases also run
//! parts of their work on the machine's other cores (`crates/inertia/src/
//! parallel.rs`), whose time this thread's figure leaves out: it is about
//! the critical path, the wall time on an idle machine.
//!
//! ```text
//! cargo run --release --example mesh_load_phases -- FILE...
//! ```
//!
//! Phases, each on its own copy of the data:
//! - `read`: the file's bytes into memory;
//! - `parse+merge`: [`load_bodies_from_bytes`] (the format's parser, mesh
//!   validation and the vertex merge of every body);
//! - `merge`: the vertex merge alone, repeated on the loaded mesh (the same
//!   vertex count as inside the load for indexed formats, and for binary STL
//!   whose loader already shares exact repeats);
//! - `parse` = `parse+merge` − `merge`;
//! - `check (fresh)`: [`prepare_solid`] on a copy of the loaded mesh built
//!   from its parts, the whole check: degenerate triangles, closure,
//!   manifold, orientation;
//! - `check`: [`prepare_solid`] on the loaded mesh as the CLI runs it (from
//!   32768 triangles the weld has found the topology on a second thread
//!   beside its tolerance pass, so what is left is orienting, the volume
//!   signs and the degenerate triangles);
//! - `integrate`: [`MeshMoments::solid`] and the mass properties;
//! - `tobj` (OBJ only): `tobj::load_obj_buf` on the raw file, the third-party
//!   parser's share;
//! - `load_bodies`: [`load_bodies`] from the path (binary STL streams the
//!   file instead of reading it whole; from 32768 triangles the weld finds
//!   the check's topology on a second thread, whose time this thread's
//!   figure leaves out); `load_bodies wall` is its wall-clock time and
//!   `load_bodies process CPU` the whole process's CPU time over it (user +
//!   system, all threads; from `/proc/self/stat` in ticks of 10 ms, so ±10 ns per
//!   triangle at 10⁶ triangles).
//!
//! `… peak B/tri`: how far the process's peak resident memory rose above its
//! resident memory at the start of `merge`, `check` and `load_bodies` (Linux;
//! the peak is reset through `/proc/self/clear_refs` before each), per
//! triangle. The mesh itself (24 bytes per triangle when closed) is held
//! before `merge` and `check` start, so it is not in their figures; memory
//! freed by an earlier phase and reused is not counted either, so the
//! `load_bodies` figure is a lower bound (the CLI's peak RSS is the whole).

use std::path::Path;
use std::time::Instant;

use kreisel::inertia::io::{MeshFormat, load_bodies, load_bodies_from_bytes};
use kreisel::inertia::{MeshMoments, TriMesh, Weld, prepare_solid};

/// CPU time of this thread in seconds, or wall time if unavailable.
fn now() -> f64 {
    static START: std::sync::OnceLock<Instant> = std::sync::OnceLock::new();
    let schedstat = std::fs::read_to_string("/proc/thread-self/schedstat").ok();
    match schedstat.and_then(|s| s.split_whitespace().next()?.parse::<u64>().ok()) {
        Some(ns) => ns as f64 * 1e-9,
        None => START.get_or_init(Instant::now).elapsed().as_secs_f64(),
    }
}

/// CPU time of the whole process (all threads, user + system) in seconds,
/// from `/proc/self/stat` (ticks of 1/100 s), if readable.
fn process_cpu() -> Option<f64> {
    let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
    // Fields after the parenthesised command name; utime and stime are
    // fields 14 and 15 of the whole line.
    let rest = stat.rsplit_once(')')?.1;
    let mut fields = rest.split_whitespace().skip(11);
    let user: f64 = fields.next()?.parse().ok()?;
    let system: f64 = fields.next()?.parse().ok()?;
    Some((user + system) / 100.0)
}

/// A field of `/proc/self/status` in bytes (`VmRSS`, `VmHWM`), if readable.
fn status_bytes(field: &str) -> Option<f64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with(field))?;
    let kb: f64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb * 1024.0)
}

/// Runs `f`: its value, the seconds it took, and how far the peak resident
/// memory rose above the resident memory at its start (bytes; 0 where
/// `/proc` cannot say). The peak is reset first (`/proc/self/clear_refs`).
fn timed<T>(f: impl FnOnce() -> T) -> (T, f64, f64) {
    let _ = std::fs::write("/proc/self/clear_refs", "5");
    let base = status_bytes("VmRSS");
    let start = now();
    let value = f();
    let seconds = now() - start;
    let peak = status_bytes("VmHWM").zip(base).map_or(0.0, |(p, b)| p - b);
    (value, seconds, peak)
}

fn phases(path: &Path) -> Result<(), String> {
    let format = MeshFormat::from_path(path).ok_or("unknown extension")?;
    let name = path.display().to_string();
    let (bytes, read, _) = timed(|| std::fs::read(path));
    let bytes = bytes.map_err(|e| e.to_string())?;
    let (bodies, load, _) = timed(|| load_bodies_from_bytes(&bytes, format, &name, path.parent()));
    let bodies = bodies.map_err(|e| e.to_string())?;
    let mesh = bodies.into_iter().next().ok_or("no body")?.mesh;
    let n = mesh.triangles().len() as f64;
    let (merged, merge, merge_mem) = timed(|| mesh.clone().welded(Weld::default()));
    let merged = merged.map_err(|e| e.to_string())?.0;
    assert_eq!(merged.vertices().len(), mesh.vertices().len());
    let parts = || TriMesh::new(mesh.vertices().to_vec(), mesh.triangles().to_vec());
    let (fresh, check_fresh, _) = timed(|| prepare_solid(parts()));
    fresh.map_err(|e| e.to_string())?;
    let (checked, check, check_mem) = timed(|| prepare_solid(mesh.clone()));
    let checked = checked.map_err(|e| e.to_string())?;
    let (mass, integrate, _) = timed(|| MeshMoments::solid(&checked.mesh).mass_properties(1000.0));
    let mass = mass.map_err(|e| e.to_string())?.mass;
    drop((checked, mesh, merged));
    let tobj = (format == MeshFormat::Obj).then(|| {
        let options = tobj::LoadOptions {
            single_index: true,
            triangulate: true,
            ..Default::default()
        };
        let (_, seconds, _) = timed(|| {
            tobj::load_obj_buf(&mut &bytes[..], &options, |_| {
                Err(tobj::LoadError::OpenFileFailed)
            })
            .map(|(models, _)| models.len())
        });
        seconds
    });
    drop(bytes);
    let wall = Instant::now();
    let cpu = process_cpu();
    let (streamed, load_path, load_mem) = timed(|| load_bodies(path));
    let load_wall = wall.elapsed().as_secs_f64();
    let load_cpu = process_cpu().zip(cpu).map(|(b, a)| b - a);
    streamed.map_err(|e| e.to_string())?;
    let ns = |s: f64| format!("{:.0}", s / n * 1e9);
    let per = |bytes: f64| format!("{:.0}", bytes / n);
    let mut row = vec![
        ("triangles", format!("{n}")),
        ("read", ns(read)),
        ("parse+merge", ns(load)),
        ("merge", ns(merge)),
        ("parse", ns(load - merge)),
        ("check (fresh)", ns(check_fresh)),
        ("check", ns(check)),
        ("integrate", ns(integrate)),
        ("load_bodies", ns(load_path)),
        ("load_bodies wall", ns(load_wall)),
        (
            "load_bodies process CPU",
            load_cpu.map_or_else(|| "?".to_owned(), ns),
        ),
        ("merge peak B/tri", per(merge_mem)),
        ("check peak B/tri", per(check_mem)),
        ("load_bodies peak B/tri", per(load_mem)),
    ];
    if let Some(t) = tobj {
        row.push(("tobj", ns(t)));
    }
    row.push(("mass (kg, 1000 kg/m^3)", format!("{mass}")));
    println!("{name}");
    for (label, value) in row {
        println!("  {label:>22}: {value}");
    }
    Ok(())
}

fn main() -> std::process::ExitCode {
    let mut status = std::process::ExitCode::SUCCESS;
    for arg in std::env::args().skip(1) {
        if let Err(e) = phases(Path::new(&arg)) {
            eprintln!("{arg}: {e}");
            status = std::process::ExitCode::FAILURE;
        }
    }
    status
}
