#!/usr/bin/env bash
# The course on JupyterHub: install (as root) and optionally start the hub. Run from the checkout:
#   sudo deploy/jupyterhub/deploy.sh install            # venv, proxy, accounts, exchange, configs, numba seed, test cache
#   sudo deploy/jupyterhub/deploy.sh start              # the hub in the foreground (Ctrl-C stops it)
#   sudo deploy/jupyterhub/deploy.sh down               # stop a hub started by start (pid file)
#   sudo deploy/jupyterhub/deploy.sh exchange           # only nbgrader's exchange (part of install)
# Settings (environment, defaults in brackets):
#   COURSE_HOME [/opt/delaunay-course]   everything the hub serves, except the venv and the homes
#   HUB_VENV    [$COURSE_HOME/venv]      the shared course venv (built from /usr/bin/python3:
#                                        the interpreter must be readable by every account)
#   HUB_INSTRUCTORS [hub-instructor]  HUB_STUDENTS [hub-student1,hub-student2,hub-student3]
#   HUB_PASSWORD    when set, every listed account gets this unix password (demo/PAM logins)
#   HUB_AUTH [pam]  HUB_PORT [8000]
#   HUB_NUMBA_SEED [all]  the numba kernels compiled once into the seed every new account's cache
#                         starts with: "all", or reference_impl.warmup groups ("2d predicates,checkers")
set -euo pipefail
REPO="$(cd "$(dirname "$0")/../.." && pwd)"
HERE="$REPO/deploy/jupyterhub"
export COURSE_HOME="${COURSE_HOME:-/opt/delaunay-course}"
export HUB_VENV="${HUB_VENV:-$COURSE_HOME/venv}"
export HUB_INSTRUCTORS="${HUB_INSTRUCTORS:-hub-instructor}"
export HUB_STUDENTS="${HUB_STUDENTS:-hub-student1,hub-student2,hub-student3}"
export HUB_STATE="${HUB_STATE:-$COURSE_HOME/state}"
EXCHANGE="$COURSE_HOME/exchange"
COURSE_ID="delaunay-course"

die() { echo "deploy.sh: $*" >&2; exit 1; }
[ "$(id -u)" = 0 ] || die "run as root: the hub starts servers as other accounts"

venv() {  # the shared venv, rebuilt only when pyproject.toml or the course's sources change
    local key
    key="$(cat "$REPO/pyproject.toml" <(cd "$REPO" && find grader reference_impl -name '*.py' -newer "$REPO/pyproject.toml" -printf '%p %T@\n' | sort) | sha256sum | cut -c1-16)"
    if [ "$(cat "$HUB_VENV/.course-key" 2>/dev/null)" != "$key" ]; then
        [ -x /usr/bin/python3 ] || die "/usr/bin/python3 is missing (apt-get install python3-venv)"
        /usr/bin/python3 -m venv "$HUB_VENV"
        "$HUB_VENV/bin/pip" install --quiet --upgrade pip
        # non-editable: the venv holds its own copy, so the checkout may stay private (0700)
        "$HUB_VENV/bin/pip" install --quiet "$REPO" 'jupyterhub>=5,<7'
        echo "$key" > "$HUB_VENV/.course-key"
    fi
    # widget state saved with a lesson, as make setup does for the checkout's venv: a lesson
    # reopened without its kernel shows the widgets' last pictures, not "model not found"
    install -D -m 0644 "$REPO/deploy/lab-overrides.json" "$HUB_VENV/share/jupyter/lab/settings/overrides.json"
    # every account's server reads the venv's etc/jupyter (sys.prefix): saves that replace the
    # notebook whole, so no concurrent read or stopped server loses a save (jupyter_server_config.py)
    install -D -m 0644 "$HERE/jupyter_server_config.py" "$HUB_VENV/etc/jupyter/jupyter_server_config.py"
    chown -R root:root "$HUB_VENV"; chmod -R go-w,go+rX "$HUB_VENV"   # read-only for every account
}

proxy() {  # configurable-http-proxy from npm, in a local prefix (deploy/jupyterhub/node/, gitignored)
    # One install at a time (make hub and the tests may run at once), and a proxy that does not
    # start (a half-written node_modules) is installed afresh rather than trusted.
    local cmd="$HERE/node/node_modules/.bin/configurable-http-proxy"
    (
        flock 9
        "$cmd" --version >/dev/null 2>&1 && exit 0
        rm -rf "$HERE/node"
        npm install --loglevel=error --no-audit --no-fund --prefix "$HERE/node" configurable-http-proxy \
            && "$cmd" --version >/dev/null || { echo "deploy.sh: npm could not install configurable-http-proxy" >&2; exit 1; }
    ) 9>"$HERE/.node.lock"
}

accounts() {
    local u
    for u in ${HUB_INSTRUCTORS//,/ } ${HUB_STUDENTS//,/ }; do
        id "$u" >/dev/null 2>&1 || useradd --create-home --shell /bin/bash "$u"
        chmod 0700 "$(getent passwd "$u" | cut -d: -f6)"      # Debian's default 0755 lets classmates read
        if [ -n "${HUB_PASSWORD:-}" ]; then echo "$u:$HUB_PASSWORD" | chpasswd; fi
    done
}

copy_problems() {  # the full problem packages assignments/<id>/ (symlinks kept) into $1, replacing old copies
    /usr/bin/python3 - "$REPO/assignments" "$1" <<'PY'
import shutil, sys
from pathlib import Path
src, dst = Path(sys.argv[1]), Path(sys.argv[2])
for p in sorted(src.iterdir()):
    if (p / "problem.yaml").is_file():
        shutil.rmtree(dst / p.name, ignore_errors=True)
        shutil.copytree(p, dst / p.name, symlinks=True, ignore=shutil.ignore_patterns(".cache", "__pycache__"))
PY
}

exchange() {  # nbgrader's exchange: every account writes in it, none can take another's folder
    local instr="${HUB_INSTRUCTORS%%,*}" course="$EXCHANGE/$COURSE_ID" d group
    mkdir -p "$COURSE_HOME"; chmod 0755 "$COURSE_HOME"
    # closed (0755) while the course's folders are checked and made: no account adds one meanwhile
    mkdir -p "$EXCHANGE"; chown root:root "$EXCHANGE"; chmod 0755 "$EXCHANGE"
    # the course's folders are made here, the instructor's, so no student can make them first (a
    # course folder of a student's would hold their fake outbound and an inbound they read);
    # nbgrader's modes, which it keeps for existing folders: inbound 0733 + setgid, plus sticky
    # (a submission's name cannot be listed, and now cannot be removed by a classmate either)
    group="$(id -gn "$instr")"
    for d in "$course" "$course/outbound" "$course/inbound"; do
        if [ -L "$d" ] || { [ -e "$d" ] && [ "$(stat -c %U "$d")" != "$instr" ]; }; then
            die "$d is not $instr's folder (a symbolic link, or made by another account): remove it and install again"
        fi
    done
    install -d -o "$instr" -g "$group" -m 0755 "$course" "$course/outbound"
    install -d -o "$instr" -g "$group" -m 3733 "$course/inbound"
    # open, sticky: only a folder's owner (or root) renames or removes it; nbgrader compares only
    # the 0777 bits of the exchange root with its 0777, so it keeps the sticky bit
    chmod 1777 "$EXCHANGE"
}

course() {
    local instr="${HUB_INSTRUCTORS%%,*}" role
    mkdir -p "$COURSE_HOME" "$HUB_STATE"
    chmod 0755 "$COURSE_HOME"; chmod 0700 "$HUB_STATE"
    exchange
    # the students' copy of the problems, readable by everyone: statements, samples, validators and
    # checkers, and a course.yaml without the hidden tests, their generators or the seed (with those
    # a student could rebuild every hidden input); the full packages stay in the instructor's course
    (cd / && "$HUB_VENV/bin/python" -m grader.course.public_problems "$REPO/assignments" "$COURSE_HOME/problems") >/dev/null
    chown -R root:root "$COURSE_HOME/problems"; chmod -R go-w,go+rX "$COURSE_HOME/problems"
    # the instructor's course root: sources, gradebook, release/submitted/autograded/feedback
    if [ ! -d "$COURSE_HOME/course" ]; then
        mkdir -p "$COURSE_HOME/course"
        cp -a "$REPO/assignments/source" "$REPO/assignments/nbgrader_config.py" "$COURSE_HOME/course/"
    fi
    copy_problems "$COURSE_HOME/course"
    chown -R "$instr:" "$COURSE_HOME/course"; chmod 0700 "$COURSE_HOME/course"
    for role in instructor student; do
        mkdir -p "$COURSE_HOME/jupyter/$role/labconfig"
        cat > "$COURSE_HOME/jupyter/$role/nbgrader_config.py" <<EOF
# written by deploy/jupyterhub/deploy.sh: the course server's system nbgrader config ($role)
c = get_config()  # noqa: F821
c.CourseDirectory.course_id = "$COURSE_ID"
c.Exchange.root = "$EXCHANGE"
EOF
    done
    echo 'c.CourseDirectory.root = "'"$COURSE_HOME/course"'"' >> "$COURSE_HOME/jupyter/instructor/nbgrader_config.py"
    cat > "$COURSE_HOME/jupyter/student/jupyter_server_config.json" <<'EOF'
{"ServerApp": {"jpserver_extensions": {"nbgrader.server_extensions.formgrader": false,
                                       "nbgrader.server_extensions.course_list": false}}}
EOF
    cat > "$COURSE_HOME/jupyter/student/labconfig/page_config.json" <<'EOF'
{"disabledExtensions": {"@jupyter/nbgrader:formgrader": true, "@jupyter/nbgrader:course-list": true,
                        "@jupyter/nbgrader:create-assignment": true,
                        "@jupyterlab/apputils-extension:announcements": true}}
EOF
    echo '{"disabledExtensions": {"@jupyterlab/apputils-extension:announcements": true}}' \
        > "$COURSE_HOME/jupyter/instructor/labconfig/page_config.json"
    chmod -R go+rX "$COURSE_HOME/jupyter"
}

warm_tests() {  # the instructor's test cache filled now, as that account (its own ~/.cache/grader, as
    # its server sets GRADER_CACHE): the first grading or sample check never waits for the tests
    local instr="${HUB_INSTRUCTORS%%,*}" home
    home="$(getent passwd "$instr" | cut -d: -f6)"
    # its numba cache starts from the seed, as the hub's pre_spawn would start it (when empty)
    (cd / && "$HUB_VENV/bin/python" -I -m grader.course.numba_seed seed "$HUB_VENV/numba-seed" "$home/.cache/numba" "$instr")
    (cd / && runuser -u "$instr" -- env HOME="$home" PATH="$HUB_VENV/bin:/usr/bin:/bin" \
        GRADER_PROBLEMS="$COURSE_HOME/course" GRADER_CACHE="$home/.cache/grader" \
        NUMBA_CACHE_DIR="$home/.cache/numba" OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 \
        "$HUB_VENV/bin/python" -m grader warm) || die "could not generate the tests into $instr's cache (see above)"
}

numba_seed() {  # the kernels compiled once, as the instructor, into a scratch cache, then installed
    # root-owned (0755/0644) as $HUB_VENV/numba-seed: the hub's pre_spawn copies it into each account
    # whose ~/.cache/numba is missing or empty (grader/course/numba_seed.py). Rebuilt when the venv
    # or the list of groups changes; numba re-checks every cached function's sources anyway.
    local instr="${HUB_INSTRUCTORS%%,*}" home groups="${HUB_NUMBA_SEED:-all}" seed="$HUB_VENV/numba-seed" key scratch
    [ "$groups" = all ] && groups=""
    key="$(cat "$HUB_VENV/.course-key")|$groups"
    if [ -f "$seed/.seed-key" ] && [ "$(cat "$seed/.seed-key")" = "$key" ]; then return 0; fi
    home="$(getent passwd "$instr" | cut -d: -f6)"
    scratch="$(mktemp -d /tmp/numba-seed.XXXXXX)"; chmod 0711 "$scratch"
    install -d -o "$instr" -m 0700 "$scratch/cache"
    (cd / && runuser -u "$instr" -- env HOME="$home" PATH="$HUB_VENV/bin:/usr/bin:/bin" OMP_NUM_THREADS=1 \
        OPENBLAS_NUM_THREADS=1 "$HUB_VENV/bin/python" -m grader.course.numba_seed build "$scratch/cache" "$groups") \
        || { rm -rf "$scratch"; die "could not compile the numba seed (see above)"; }
    chown root:root "$scratch/cache"; chmod 0700 "$scratch/cache"   # the instructor's part is over
    rm -rf "$seed.new"
    # regular files only, root's own copy (no symbolic link of the scratch followed or kept)
    "$HUB_VENV/bin/python" -I -m grader.course.numba_seed copy "$scratch/cache" "$seed.new" >/dev/null \
        || { rm -rf "$scratch" "$seed.new"; die "could not install the numba seed"; }
    rm -rf "$scratch"
    echo "$key" > "$seed.new/.seed-key"
    chown -R root:root "$seed.new"; chmod -R u=rwX,go=rX "$seed.new"
    rm -rf "$seed"; mv "$seed.new" "$seed"
    "$HUB_VENV/bin/python" -I -m grader.course.numba_seed check "$seed" >/dev/null \
        || die "the numba seed $seed is not trusted: $("$HUB_VENV/bin/python" -I -m grader.course.numba_seed check "$seed")"
}

start() {
    export PATH="$HUB_VENV/bin:$PATH"
    export HUB_PROXY="$HERE/node/node_modules/.bin/configurable-http-proxy"
    cd "$HUB_STATE"
    exec "$HUB_VENV/bin/jupyterhub" -f "$HERE/jupyterhub_config.py"
}

down() {
    local f
    for f in "$HUB_STATE/jupyterhub.pid" "$HUB_STATE/proxy.pid"; do
        [ -f "$f" ] && kill "$(cat "$f")" 2>/dev/null || true
    done
}

case "${1:-}" in
    install) venv; proxy; accounts; course; numba_seed; warm_tests; echo "installed under $COURSE_HOME (venv $HUB_VENV)";;
    start) start;;
    down) down;;
    exchange) exchange; echo "exchange ready: $EXCHANGE";;
    *) die "usage: deploy.sh install|start|down|exchange";;
esac
