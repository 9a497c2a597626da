#!/usr/bin/env bash
# Regenerates everything in validation/studies/: the papers' parameter studies run with
# `rollerdyn sweep`, each merged with the published table (validation/published/) into one CSV
# (ours beside theirs), the cam-vs-crank comparison (Loveikin and Pochka, cam drive with optimal
# reversal) and the two-rotor chain check (Dyomin (two rotors)). The last step writes every *.md
# page here from those tables (`rollerdyn validate --studies`): no page is written by hand.
#
#   bash validation/studies/run.sh            # from the repository root, after building
#   ROLLERDYN=build-studies/rollerdyn bash validation/studies/run.sh
#
# Cost: the reduced-model sweeps take seconds; the multibody points and the multibody cam
# comparison a few minutes on one core. Sweeps use 2 worker threads (`--threads`).
set -euo pipefail
cd "$(dirname "$0")/../.."
R=${ROLLERDYN:-build/rollerdyn}
OUT=validation/studies
PUB=validation/published
[ -x "$R" ] || { echo "no rollerdyn executable at $R (set ROLLERDYN=...)" >&2; exit 2; }

# A point that fails is recorded in its row and the sweep exits 3; keep going, the CSV says why.
# Exit 3: some point failed to run; 4: some drive stalls or rocks (both reported in sweep.csv).
sweep() { local rc=0; "$R" sweep "$@" || rc=$?; [ $rc -eq 0 ] || [ $rc -eq 3 ] || [ $rc -eq 4 ]; }

# join OURS PUB KEYS... : print ours (selected columns, renamed "ours_*") beside the published
# row with the same key values. Column names are looked up in the headers (a unit in brackets,
# e.g. delta[-], is ignored); '#' lines skipped.
# usage: join_tables ours.csv ours_key_cols ours_cols pub.csv pub_key_cols pub_cols > out.csv
join_tables() {
  awk -F, -v OFS=, -v okeys="$2" -v ocols="$3" -v pkeys="$5" -v pcols="$6" '
    function idx(hdr, names, out,   n, i, k, a, h) {
      n = split(names, a, " ")
      for (i = 1; i <= n; i++) { out[i] = 0; for (k in hdr) { h = hdr[k]; sub(/\[.*\]$/, "", h); if (h == a[i]) out[i] = k }
        if (!out[i]) { print "join_tables: no column " a[i] > "/dev/stderr"; exit 2 } }
      return n
    }
    function keyof(f, ki, nk,   s, i) { s = ""; for (i = 1; i <= nk; i++) s = s "|" (f[ki[i]] + 0); return s }
    FNR == 1 { file++ }
    /^#/ { next }
    file == 1 && !oh { split($0, H1, ","); for (i in H1) h1[i] = H1[i]; nok = idx(h1, okeys, OK); noc = idx(h1, ocols, OC); oh = 1; next }
    file == 2 && !ph { split($0, H2, ","); for (i in H2) h2[i] = H2[i]; npk = idx(h2, pkeys, PK); npc = idx(h2, pcols, PC); ph = 1
      split(okeys, kn, " "); split(ocols, on, " "); split(pcols, pn, " ")
      s = ""; for (i = 1; i <= nok; i++) s = s (i > 1 ? OFS : "") kn[i]
      for (i = 1; i <= noc; i++) s = s OFS "ours_" on[i]
      for (i = 1; i <= npc; i++) s = s OFS "published_" pn[i]
      print s; next }
    file == 1 { n = split($0, f, ","); k = keyof(f, OK, nok); ok[k] = 1; order[++no] = k
      s = ""; for (i = 1; i <= noc; i++) s = s OFS f[OC[i]]; ours[k] = s; kv[k] = ""
      for (i = 1; i <= nok; i++) kv[k] = kv[k] (i > 1 ? OFS : "") f[OK[i]]; next }
    file == 2 { n = split($0, f, ","); k = keyof(f, PK, npk)
      s = ""; for (i = 1; i <= npc; i++) s = s OFS f[PC[i]]; pub[k] = s; next }
    END { for (j = 1; j <= no; j++) { k = order[j]; p = (k in pub) ? pub[k] : ""
            if (!(k in pub)) for (i = 1; i <= npc; i++) p = p OFS
            print kv[k] ours[k] p } }
  ' "$1" "$4"
}

# --- Loveikin and Pochka (2007): crank offset 0...180 deg, two carts on opposite sides, rigid drive ---------------
sweep model/recuperative-2cart.yaml --param crank.offset_deg --values 0:180:10 --model reduced \
  --minimize delta --out $OUT/loveikin2007_dphi
sweep model/recuperative-2cart.yaml --param crank.offset_deg --values 0,45,90,135,180 --model multibody \
  --minimize delta --out $OUT/loveikin2007_dphi_multibody
COLS="omega_crank_min omega_crank_max omega_crank_mean omega_crank_midrange delta eps_crank_abs_max H k_p steady_state_reached"
join_tables $OUT/loveikin2007_dphi/sweep.csv crank.offset_deg "$COLS" \
  $PUB/loveikin2007_table.csv dphi_deg "omega_min omega_max omega_mean delta eps_max H k_p" > $OUT/loveikin2007_dphi.csv
join_tables $OUT/loveikin2007_dphi_multibody/sweep.csv crank.offset_deg "$COLS" \
  $PUB/loveikin2007_table.csv dphi_deg "delta eps_max H k_p" > $OUT/loveikin2007_dphi_multibody.csv

# --- the energy-balanced drive paper (authors not printed): flywheel 0...1000 kg*m^2 on the crankshaft, three carts at 120 deg ----------------
# A flywheel slows the approach to steady state (time constant ~ J/(dM/dω)); 40 s leaves every
# point at steady state (steady_state_reached column).
sweep model/energy-balanced-3cart.yaml --param flywheel.inertia --values 0:1000:50 --model reduced \
  --set simulation.t_end=40 --minimize delta --out $OUT/energy_balanced_flywheel
join_tables $OUT/energy_balanced_flywheel/sweep.csv flywheel.inertia "$COLS" \
  $PUB/energy_balanced_table1.csv flywheel_inertia "omega_min omega_max omega_mean delta eps_max H k_p" > $OUT/energy_balanced_flywheel.csv

# --- Loveikin, Pochka, Romasevych (2018): crank offset 0...90 deg for coupling damping 2000 and 8000 (Table 1) -------------
# Started at the nominal crank speed ω_n/u = 102.1/9.8 = 10.42 rad/s and run for 20 s, exactly as
# the Table 1 comparison of `rollerdyn validate` (validation/report.md): Table 1 lists steady
# swings, and from rest the motor cannot turn the as-printed roller loads at some offsets (the
# report's sensitivity table runs that start). 20 s leaves >= 5 steady revolutions where there are any.
TCOLS="coupling_torque_swing twist_swing twist_rate_swing twist_accel_swing delta omega_crank_mean steady_state_reached"
TPUB="coupling_torque_swing twist_swing twist_rate_swing twist_accel_swing"
START="--set initial.crank_speed=10.42 --set simulation.t_end=20"
sweep model/balanced-4cart.yaml --param coupling.damping --values 2000,8000 \
  --param crank.offset_deg --values 0:90:10 --model reduced $START \
  --minimize coupling_torque_swing --out $OUT/loveikin2018_dphi_damping
join_tables $OUT/loveikin2018_dphi_damping/sweep.csv "crank.offset_deg coupling.damping" "$TCOLS" \
  $PUB/loveikin2018_table1.csv "dphi_deg k" "$TPUB" > $OUT/loveikin2018_dphi_damping.csv
sweep model/balanced-4cart.yaml --param coupling.damping --values 2000,8000 \
  --param crank.offset_deg --values 60,90 --model multibody $START \
  --out $OUT/loveikin2018_dphi_damping_multibody
join_tables $OUT/loveikin2018_dphi_damping_multibody/sweep.csv "crank.offset_deg coupling.damping" "$TCOLS" \
  $PUB/loveikin2018_table1.csv "dphi_deg k" "$TPUB" > $OUT/loveikin2018_dphi_damping_multibody.csv

# --- Loveikin, Pochka, Romasevych (2018): coupling stiffness, where is the minimum of the coupling torque swing? -----------
# The paper finds c = 200000 N*m/rad "by a numerical experiment" before adding damping (eq. (39)),
# so damping 0 and the scene's 8000 are both swept (Δφ = 90°, the paper's machine).
C_VALUES=10000,25000,50000,75000,100000,125000,150000,175000,200000,225000,250000,300000,400000,600000,1000000
for k in 0 8000; do
  sweep model/balanced-4cart.yaml --param coupling.stiffness --values $C_VALUES --model reduced $START \
    --set coupling.damping=$k --minimize coupling_torque_swing --out $OUT/loveikin2018_stiffness_k$k
done

# --- Loveikin and Pochka (cam drive): cam drive against a crank of equal stroke and cycle time --------------------------
"$R" cam-profile model/cam-drive.yaml --compare --model multibody --out $OUT/cam
cp $OUT/cam/cam_vs_crank.csv $OUT/cam_vs_crank.csv

# --- Dyomin (two rotors): two rotors on an elastic chain, simulation vs closed form ------------------------
"$R" chain --out $OUT/chain
"$R" chain --omega 23.15 --out $OUT/chain_resonance3   # p0 = 69.45 rad/s ≈ 3ω
# --- Start-up from rest with each motor law (motor.model: static Kloss, the equivalent circuit and the -----
# space-phasor machine, both fitted to the motor's catalogue; docs/startup.md) ---------------------------
# Each paper's machine started from rest, direct on line, in the multibody model (two scenes' own start
# is at nominal speed where Kloss's starting torque cannot move the carts), and the Table 1 offsets of
# Loveikin, Pochka, Romasevych (2018) from rest with each law (reduced model, 20 s as for Table 1).
# recuperative-2cart has no catalogue block (its printed motor data are not one catalogue motor), so
# only its Kloss point runs; the others are recorded as invalid with the reason.
# One `simulate` per machine and law; its summary.json (start_up: docs/startup.md) is what the page
# reads, the tables are not kept (they would be ~0.5 MB each).
for scene in balanced-4cart recuperative-2cart energy-balanced-3cart; do
  for law in kloss circuit park; do
    d=$OUT/startup_$scene/$law
    mkdir -p $d
    rc=0; "$R" simulate model/$scene.yaml --set motor.model=$law --set initial.crank_speed=0 --out $d > $d/console.txt 2>&1 \
        || rc=$?
    # 3: a run that ended early, 4: a drive that does not start; both are results of this study.
    if [ $rc -eq 0 ] || [ $rc -eq 3 ] || [ $rc -eq 4 ]; then rm -f $d/timeseries.csv $d/reactions.csv
    else why=$(tail -1 $d/console.txt); echo "not run: $why" > $d/console.txt; fi
  done
done
sweep model/balanced-4cart.yaml --param motor.model --values kloss,circuit,park --param crank.offset_deg --values 0:90:10 \
  --param coupling.damping --values 2000,8000 --model reduced --set initial.crank_speed=0 --set simulation.t_end=20 \
  --out $OUT/startup_loveikin2018_table1

# --- the pages: every *.md here, written from the tables above -------------------------------------
"$R" validate --studies $OUT
echo "studies written to $OUT/"
