# Sourced by the reliability tests (needs: here): the project's
# environment, strict about unset variables, and no __pycache__ in the
# source tree.
export PYTHONDONTWRITEBYTECODE=1
set +u
source "$here/../../../etc/bashrc" || exit 1
set -u
