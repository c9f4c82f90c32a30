#!/bin/sh
# A rho-shaped trajectory of about R reflections (bench/RESULTS.md, "A rho
# cycle of 10^9 reflections"): the channel between the mirrors y = 0 and
# y = 1 from x = 0 to x = n, closed by a mirror x = n, with a one-way mirror
# x+ m (it acts on rays moving toward -x) half way. The ray leaves the
# origin along (1, 1), reflects at x = 1, 2, ..., passes the one-way
# mirror's back, turns at x = n and is caught between x = m and x = n:
# tail m - 1, period 2 (n - m) (tests/test_one_sided_lattice.cpp checks the
# closed form). With n = 2k and m = k: tail k - 1, period 2k, 3k - 1
# reflections.
#
#   bench/one_way_channel.sh 333333334 > /tmp/channel.scene   # 10^9 - 1 reflections
#   /usr/bin/time -f '%M KB %e s' ./build/cli/orthoray solve /tmp/channel.scene --json
set -eu
k=${1:?usage: one_way_channel.sh K (tail K - 1, period 2K)}
n=$((2 * k))
cat <<SCENE
dim 2
mirror y 0 x 0 $n
mirror y 1 x 0 $n
mirror x $n y 0 1
mirror x+ $k y 0 1
ray 0 0 1 1
target -1 -1
SCENE
