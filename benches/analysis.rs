//! Criterion timings of `kreisel_analysis` (issue 28): one steady
//! motion's verdict (the Jacobian by dual numbers, the reduction, the
//! eigenvalues and modes) for each family, and whole stability maps — the
//! sleeping top over 200 × 200 (spin × centre-of-mass offset) and the
//! rolling disk over 200 × 200 (speed × gravity) — on two threads, with
//! their boundaries bisected to rounding.
//!
//! ```text
//! cargo bench --bench analysis
//! ```
//!
//! The numbers are in `BENCHMARKS.md` ("Stability (issue 28)").

use std::hint::black_box;
use std::num::NonZeroUsize;
use std::time::Duration;

use criterion::{Criterion, criterion_group, criterion_main};
use glam::DVec3;
use kreisel::dynamics::Friction;
use kreisel_analysis::{
    FreeBodyRotation, HeavyTopPivot, LEINE_GLOCKER, Linearisation, PrecessingTop, Precession,
    Rattleback, RollingDisk, StabilityMap, Sweep, TippeTop,
};

fn verdicts(c: &mut Criterion) {
    let mut group = c.benchmark_group("stability_verdict");
    group
        .sample_size(50)
        .measurement_time(Duration::from_secs(3));
    let free = FreeBodyRotation::try_new(DVec3::new(1.0, 2.0, 3.0)).unwrap();
    let x = free.about_axis(1, 2.0).unwrap();
    group.bench_function("free_body_3d", |b| {
        b.iter(|| Linearisation::try_new(black_box(&free), black_box(&x)).unwrap())
    });
    let top = HeavyTopPivot::try_new(
        DVec3::new(0.03, 0.03, 0.01),
        DVec3::new(0.0, 0.0, 0.1),
        9.81,
    )
    .unwrap();
    let x = top.sleeping(60.0).unwrap();
    group.bench_function("sleeping_top_6d", |b| {
        b.iter(|| Linearisation::try_new(black_box(&top), black_box(&x)).unwrap())
    });
    let precessing = PrecessingTop::try_new(0.03, 0.01, 0.981).unwrap();
    let x = precessing.steady(0.5, 60.0, Precession::Slow).unwrap();
    group.bench_function("steady_precession_4d", |b| {
        b.iter(|| Linearisation::try_new(black_box(&precessing), black_box(&x)).unwrap())
    });
    let disk = RollingDisk::thin(0.005, 0.012, 9.81).unwrap();
    let x = disk.rolling_straight(0.5).unwrap();
    group.bench_function("rolling_disk_5d", |b| {
        b.iter(|| Linearisation::try_new(black_box(&disk), black_box(&x)).unwrap())
    });
    let rattleback = Rattleback::kane_levinson().unwrap();
    let x = rattleback.spinning_upright(5.0).unwrap();
    group.bench_function("rattleback_6d", |b| {
        b.iter(|| Linearisation::try_new(black_box(rattleback.field()), black_box(&x)).unwrap())
    });
    let tippe = TippeTop::try_new(LEINE_GLOCKER, Friction::try_viscous(0.3).unwrap()).unwrap();
    let x = tippe.spinning_upright(180.0).unwrap();
    group.bench_function("tippe_top_viscous_9d", |b| {
        b.iter(|| Linearisation::try_new(black_box(tippe.field()), black_box(&x)).unwrap())
    });
    group.finish();
}

fn maps(c: &mut Criterion) {
    let mut group = c.benchmark_group("stability_map_200x200_2threads");
    group
        .sample_size(10)
        .measurement_time(Duration::from_secs(20));
    let two = NonZeroUsize::new(2);
    let axes = [
        Sweep::try_new("spin", 0.0, 80.0, 200).unwrap(),
        Sweep::try_new("com_offset", 0.02, 0.3, 200).unwrap(),
    ];
    // 1 kg, I = (0.02, 0.02, 0.01) about the centre of mass, l from the pivot.
    let sleeping = |p: &[f64]| {
        let l = p[1];
        let top = HeavyTopPivot::try_new(
            DVec3::new(0.02 + l * l, 0.02 + l * l, 0.01),
            DVec3::new(0.0, 0.0, l),
            9.81,
        )?;
        Linearisation::try_new(&top, &top.sleeping(p[0])?)
    };
    group.bench_function("sleeping_top", |b| {
        b.iter(|| StabilityMap::try_new(&axes, two, sleeping).unwrap())
    });
    let axes = [
        Sweep::try_new("speed", 0.0, 1.0, 200).unwrap(),
        Sweep::try_new("gravity", 1.0, 20.0, 200).unwrap(),
    ];
    let disk = |p: &[f64]| {
        let coin = RollingDisk::thin(0.005, 0.012, p[1])?;
        Linearisation::try_new(&coin, &coin.rolling_straight(p[0])?)
    };
    group.bench_function("rolling_disk", |b| {
        b.iter(|| StabilityMap::try_new(&axes, two, disk).unwrap())
    });
    group.finish();
}

criterion_group!(benches, verdicts, maps);
criterion_main!(benches);
