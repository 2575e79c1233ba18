#!/usr/bin/env bash
# Every test, Rust and Python: `cargo test --locked`; then the Rerun recording's test
# (tests/show.rs `recording`, which decodes a written .rrd) with the `rerun` feature, in the
# `recording` profile, whose dependencies build unoptimised (the Rerun SDK's hundreds of
# crates build in a fraction of the time they take optimised); then the Python package built
# into a virtual environment (target/python-venv) and its pytest suite (python/tests).
#
# Needs python3 (≥ 3.9, with venv); installs example-robot-data (the arms of
# tests/corpus.rs, named by EYEHAND_ROBOT_DATA), xacro (tests/xacro.rs, its folder named by
# EYEHAND_XACRO_DIR), maturin, gymnasium, numpy, scikit-learn and
# pytest from PyPI into the environment. The package is built in cargo's `dev` profile so
# that it reuses the dependencies `cargo test` just compiled (`pip install ./python` builds
# the release wheel a user installs).
set -euo pipefail
cd "$(dirname "$0")/.."

venv=target/python-venv
[ -x "$venv/bin/python" ] || python3 -m venv "$venv"
# The public robot collection tests/corpus.rs runs its arms from (data only, hence no deps),
# and the xacro program tests/xacro.rs expands xacro files with (pure Python; YAML, which
# only its load_yaml needs, left out).
"$venv/bin/pip" install --quiet --disable-pip-version-check --no-deps \
    example-robot-data==6.0.0 xacro==2.1.1
purelib=$("$venv/bin/python" -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')
export EYEHAND_ROBOT_DATA="$purelib/cmeel.prefix/share/example-robot-data"
export EYEHAND_XACRO_DIR="$PWD/$venv/bin"

cargo test --locked
cargo test --locked --features rerun --profile recording --test show recording

"$venv/bin/pip" install --quiet --disable-pip-version-check \
    maturin gymnasium numpy scikit-learn pytest
rm -rf target/python-wheel
"$venv/bin/maturin" build --quiet --locked --profile dev \
    --manifest-path python/Cargo.toml --interpreter "$venv/bin/python" --out target/python-wheel
"$venv/bin/pip" install --quiet --disable-pip-version-check --force-reinstall --no-deps \
    target/python-wheel/eyehand-*.whl

EYEHAND_BIN="$PWD/target/debug/eyehand" "$venv/bin/python" -m pytest -q python/tests
