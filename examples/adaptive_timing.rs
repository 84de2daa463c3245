//! The adaptive run of punch-b40 with E elements under the punch (p = 8; default 64, i.e.
//! 513 contact points) timed step by step, for docs/performance.md (issue 9):
//! `cargo run --release --example adaptive_timing [E]`. Prints the set-up and integration
//! (wall clock), the thread's CPU time after the first step (which excludes time the
//! process was descheduled on a loaded machine), minor page faults, the steps that took
//! over 1.5 ms (factorisations; `TRACE=1` lists them with the k of each run of steps), the
//! mean of the others, and a checksum of the last pressures and shape.

// The allocator of the `wearfem` binary (src/cli/main.rs), so that the figures are the command's.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

use std::time::Instant;
use wearfem::driver;
use wearfem::problem::Problem;

fn minflt() -> u64 {
    let s = std::fs::read_to_string("/proc/self/stat").unwrap();
    let after = &s[s.rfind(')').unwrap() + 2..];
    after.split_whitespace().nth(7).unwrap().parse().unwrap()
}
fn cpu() -> f64 {
    let mut ts = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut ts) };
    ts.tv_sec as f64 + 1e-9 * ts.tv_nsec as f64
}

fn main() {
    let mut f1 = 0u64;
    let mut c1 = 0.0;
    let e: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(64);
    let text = wearfem::examples::refined_punch("punch-b40", e).unwrap();
    let text = text.replace("steps = 1700 ", "steps = 100000 ").replace(
        "record = [1, 2, 50, 100, 200, 500, 1000, 1699, 1700]",
        "record = []\n\n[wear.adaptive]\n",
    );
    let p = Problem::from_toml(&text, "x").unwrap();
    let t0 = Instant::now();
    let mut last = Instant::now();
    let mut times: Vec<(usize, usize, f64, usize)> = vec![];
    let run = driver::wear(&p, None, |r| {
        let now = Instant::now();
        if r.step == 1 {
            f1 = minflt();
            c1 = cpu();
        }
        times.push((r.step, r.k, (now - last).as_secs_f64(), r.solves));
        last = now;
    })
    .unwrap();
    let total = t0.elapsed().as_secs_f64();
    let (f2, c2) = (minflt(), cpu());
    println!(
        "faults after step 1: {}, cpu after step 1 {:.4} s, cpu total {:.4}",
        f2 - f1,
        c2 - c1,
        c2
    );
    let h = &run.history;
    let slow: Vec<_> = times.iter().filter(|t| t.2 > 1.5e-3).collect();
    let slow_sum: f64 = slow.iter().map(|t| t.2).sum();
    let fast: Vec<f64> = times
        .iter()
        .filter(|t| t.2 <= 1.5e-3)
        .map(|t| t.2)
        .collect();
    let fast_sum: f64 = fast.iter().sum();
    println!(
        "setup {:.4} run {:.4} total {:.4} steps {} half {} solves {} | slow {} steps {:.4}s | fast mean {:.1} us sum {:.4}",
        run.setup_seconds, run.run_seconds, total, h.steps.len(), h.steps.last().unwrap().half_period, h.solves,
        slow.len(), slow_sum, 1e6 * fast_sum / fast.len() as f64, fast_sum
    );
    if std::env::var("TRACE").is_ok() {
        for t in &slow {
            println!("slow step {} k {} {:.2} ms", t.0, t.1, 1e3 * t.2);
        }
        let mut ks: Vec<(usize, usize)> = vec![];
        for t in &times {
            if ks.last().map(|x| x.0) != Some(t.1) {
                ks.push((t.1, 0));
            }
            ks.last_mut().unwrap().1 += 1;
        }
        println!("k runs: {:?}", ks);
    }
    // pressure fingerprint
    let s: f64 = h.p_plus.iter().sum::<f64>() + h.p_minus.iter().sum::<f64>();
    let sh: f64 = h.shape.iter().map(|x| x * x).sum::<f64>();
    println!("fingerprint p {:.15e} shape {:.15e}", s, sh);
}
#[allow(dead_code)]
fn dbg() {}
