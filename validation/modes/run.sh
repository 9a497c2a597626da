#!/bin/sh
# Regenerates validation/modes/: the torsional modes, Campbell diagrams and stability charts of the
# shipped machines (`rollerdyn modes`) and the checks of the modal analysis
# (`rollerdyn validate --modes-only`: validation/modes/validation.md and validation.json).
# Run from the repository root after building; ROLLERDYN names the binary (default build/rollerdyn).
set -e
B=${ROLLERDYN:-build/rollerdyn}
# Loveikin, Pochka, Romasevych (2018): the paper's coupling c = 200000 N*m/rad; charts over c and the
# crank speed at k = 0 (undamped, for the zones) and at the paper's two dampings (Table 1), and over c
# and k with those two marked.
$B modes model/balanced-4cart.yaml --damping 0 --damping 2000 --damping 8000 \
   --mark-damping 2000 --mark-damping 8000 --grid 40x24 --out validation/modes/balanced-4cart
# The rigid-drive papers' machines: what an elastic coupling of stiffness c would do.
$B modes model/recuperative-2cart.yaml --grid 40x24 --out validation/modes/recuperative-2cart
$B modes model/energy-balanced-3cart.yaml --grid 40x24 --out validation/modes/energy-balanced-3cart
$B modes model/cam-drive.yaml --out validation/modes/cam-drive
$B validate --modes-only --out validation
