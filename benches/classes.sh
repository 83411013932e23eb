# shellcheck shell=bash
# The five timing classes of docs/table4.md (issue 17), for the scripts
# that time them (`source benches/classes.sh`, from the repository root):
# degree-2 rigid, degree-2 affine, degree-4 affine, Example 5.1, tumbling.
CLASSES=(
  benches/scenes/rigid-deg2.toml
  benches/scenes/affine-deg2.toml
  benches/scenes/affine-rational-deg2.toml
  tests/scenes/paper-example-5-1.toml
  tests/scenes/rigid-tumbling.toml
)
