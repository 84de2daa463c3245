"""Example 1 (punch-b40): how friction and pin height shape the steady worn state.

A notebook-style script: run it cell by cell in Jupyter (the `# %%` markers) or at once,

    python python/examples/study.py [OUT_DIR]      # default out/python-study

It sweeps the friction coefficient μ and the height of the plate's pin above the contact
(l_z = pin z − 100 mm), prints the study table, and writes two figures: the steady '+'/'−'
pressure families (steady-pressure.png) and the worn shapes (steady-shape.png).
Units: mm, MPa.
"""

# %%
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import wearfem  # noqa: E402

out = Path(sys.argv[1] if len(sys.argv) > 1 else "out/python-study")
out.mkdir(parents=True, exist_ok=True)
punch = wearfem.Problem.builtin("punch-b40")
frictions = [0.0, 0.1, 0.2, 0.3]
pin_heights = [10.0, 40.0, 70.0]  # l_z, mm above the contact edge z = 100 mm
grid = {"contact.friction": frictions, "plate.pin": [[1100.0, 100.0 + h] for h in pin_heights]}

# %% The table: one row per variant (threads: the library releases the GIL).
with ThreadPoolExecutor() as pool:
    table = wearfem.study(punch, grid, executor=pool)
print(table[["contact.friction", "plate.pin", "status", "peak_p_plus", "peak_p_minus", "shape_range", "seconds"]].to_string())

# %% The profiles of every variant.
variants = {(mu, h): punch.with_overrides({"contact.friction": mu, "plate.pin": [1100.0, 100.0 + h]}) for h in pin_heights for mu in frictions}
with ThreadPoolExecutor() as pool:
    results = dict(zip(variants, pool.map(lambda p: p.steady(), variants.values())))

colours = plt.cm.viridis([i / (len(frictions) - 1) for i in range(len(frictions))])

# %% Pressure families: one panel per pin height, '+' solid and '−' dashed, colour = μ.
fig, axes = plt.subplots(1, len(pin_heights), figsize=(13, 4.2), sharey=True)
for ax, h in zip(axes, pin_heights):
    for colour, mu in zip(colours, frictions):
        s = results[(mu, h)]
        if not s.converged:
            # The last iterate of a failed solve is no result: named, not drawn.
            ax.plot([], [], color=colour, label=f"μ = {mu}: not converged, not drawn")
            continue
        ax.plot(s.x - 1100, s.p_plus, color=colour, label=f"μ = {mu}")
        ax.plot(s.x - 1100, s.p_minus, color=colour, ls="--")
    ax.set_title(f"pin {h:.0f} mm above the contact")
    ax.set_xlabel("x − 1100 (mm)")
    ax.grid(alpha=0.3)
axes[0].set_ylabel("steady pressure (MPa): p⁺ solid, p⁻ dashed")
for ax in axes:
    ax.legend(fontsize=7)
fig.suptitle("Example 1 (punch-b40): steady contact pressure, p⁺ + p⁻ = 2p̃ = 33.3 MPa")
fig.tight_layout()
fig.savefig(out / "steady-pressure.png", dpi=110)

# %% Worn shapes, shifted to zero at the punch's centre.
fig, axes = plt.subplots(1, len(pin_heights), figsize=(13, 4.2), sharey=True)
for ax, h in zip(axes, pin_heights):
    for colour, mu in zip(colours, frictions):
        s = results[(mu, h)]
        if not s.converged:
            ax.plot([], [], color=colour, label=f"μ = {mu}: not converged, not drawn")
            continue
        centre = s.shape[len(s.shape) // 2]
        ax.plot(s.x - 1100, (s.shape - centre) * 1e3, color=colour, label=f"μ = {mu}")
    ax.set_title(f"pin {h:.0f} mm above the contact")
    ax.set_xlabel("x − 1100 (mm)")
    ax.grid(alpha=0.3)
axes[0].set_ylabel("worn shape − shape at x = 1100 (µm)")
for ax in axes:
    ax.legend(fontsize=7)
fig.suptitle("Example 1 (punch-b40): steady worn shape")
fig.tight_layout()
fig.savefig(out / "steady-shape.png", dpi=110)
print(f"figures in {out}/")
