# The course's two commands (see README.md):
#   make demo   set everything up, then run the headless tour of the course
#   make test   set everything up, then run the whole test suite
# Other targets: make lab (open the lessons in JupyterLab), make instructor (formgrader, in assignments/), make bench, make setup, make warm, make clean,
#   make hub / make hub-down (the course on JupyterHub with an instructor and three students, as root).

PYTHON ?= python3
VENV   ?= .venv
PY     := $(VENV)/bin/python
STAMP  := $(VENV)/.installed
LAB_OVERRIDES := $(VENV)/share/jupyter/lab/settings/overrides.json

.PHONY: setup warm demo test lab instructor bench clean chromium bubblewrap gxx hub hub-install hub-down

setup: $(STAMP) $(LAB_OVERRIDES)

$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -e '.[dev]'
	touch $(STAMP)

# JupyterLab does not save widget state by default, and a saved lesson reopened without running
# then shows "Error displaying widget: model not found" where every widget was (JupyterLab renders
# only the widget view of an output, never the PNG beside it). The venv's overrides.json turns
# saving on for this JupyterLab (deploy/jupyterhub/deploy.sh puts the same file in the hub's venv): reopened, every widget shows its last picture (checked in chromium).
$(LAB_OVERRIDES): $(STAMP) deploy/lab-overrides.json
	mkdir -p $(dir $(LAB_OVERRIDES))
	cp deploy/lab-overrides.json $(LAB_OVERRIDES)

# Compile every numba kernel into numba's cache (a few seconds when nothing changed), so that
# no lesson, problem or test waits for a compile; see reference_impl/warmup.py. Then generate every
# problem's hidden tests into the grader's cache (.cache/grader; kept while the packages do not
# change), so that no judging waits for them; see grader/problems/cache.py.
warm: setup
	$(PY) -m reference_impl warm
	$(PY) -m grader warm

demo: warm
	$(PY) -m reference_impl demo

# Test files run in parallel (pytest-xdist); a module that builds one expensive fixture (the
# nbgrader class, the JupyterLab server) stays on one worker through its xdist_group mark.
JOBS ?= 2
test: warm chromium bubblewrap gxx
	$(PY) -m pytest -n $(JOBS) --dist loadgroup --durations=40

# JupyterLab refuses to run as root without --allow-root (course containers and CI run as root).
# LAB_ARGS passes extra options, e.g. make lab LAB_ARGS="--no-browser --port=8899".
LAB_ROOT := $(if $(filter 0,$(shell id -u)),--allow-root,)
LAB_ARGS ?=
# The hub's server configuration (deploy/jupyterhub/jupyter_server_config.py) for the local
# JupyterLab too: saves replace the notebook whole, so a second tab, a read while saving or a
# stopped server never loses a save (deploy/jupyterhub/README.md, "Saves").
SERVER_CONFIG := --config=$(CURDIR)/deploy/jupyterhub/jupyter_server_config.py

# $(call apt_need,COMMAND,PACKAGE,WHAT HAPPENS WITHOUT IT): install PACKAGE with apt-get when
# COMMAND is missing and we are root, else say what its absence costs.
apt_need = command -v $(1) >/dev/null 2>&1 || { command -v apt-get >/dev/null 2>&1 && [ "$$(id -u)" = 0 ] \
	  && apt-get update -qq && apt-get install -y -qq $(2); } \
	  || echo "$(2) is not installed: $(3) (apt-get install $(2))"

# The browser test drives Debian's chromium (Playwright never downloads a browser here).
chromium:
	@$(call apt_need,chromium,chromium,tests/browser will be skipped)

# The C++ reference solutions (solutions/<id>/*.cpp, benchmarks/bench_cpp_solutions.py) compile with Debian's g++.
gxx:
	@$(call apt_need,g++,g++,the C++ solutions' test will be skipped)

# The jail (grader/jail/): without bubblewrap root grades in the fallback namespaces jail and an
# ordinary account refuses to grade (python -m grader.sandbox says what this machine gives).
bubblewrap:
	@$(call apt_need,bwrap,bubblewrap,root grades in the fallback jail and an ordinary account refuses to grade)

lab: warm $(LAB_OVERRIDES)
	$(VENV)/bin/jupyter lab $(SERVER_CONFIG) $(LAB_ROOT) $(LAB_ARGS) notebooks

# The instructor's JupyterLab: started in the course folder (assignments/), where formgrader finds
# nbgrader_config.py and the gradebook (started anywhere else it shows "No data available"), with
# the venv's bin/ on PATH (nbgrader calls alembic).
instructor: warm $(LAB_OVERRIDES)
	cd assignments && PATH="$(abspath $(VENV))/bin:$$PATH" "$(abspath $(VENV))/bin/jupyter" lab $(SERVER_CONFIG) $(LAB_ROOT) $(LAB_ARGS)

bench: warm
	$(PY) benchmarks/bench_delaunay.py

clean:
	rm -rf $(VENV) build .pytest_cache .hypothesis

# The course on JupyterHub (deploy/jupyterhub/README.md), as root: the shared venv (build/hub-venv,
# rebuilt when pyproject.toml or the sources change), the proxy from npm, the accounts hub-instructor
# and hub-student1..3 with one password (build/hub/password), then the hub in the foreground on a free
# port (HUB_PORT=... to choose). Ctrl-C or `make hub-down` stops the hub and every server it started.
HUB_ENV = COURSE_HOME=$(CURDIR)/build/hub HUB_VENV=$(CURDIR)/build/hub-venv
hub-install:
	@mkdir -p build/hub && [ -s build/hub/password ] || (umask 077; /usr/bin/python3 -c 'import secrets; print(secrets.token_urlsafe(9))' > build/hub/password)
	$(HUB_ENV) HUB_PASSWORD=$$(cat build/hub/password) deploy/jupyterhub/deploy.sh install

hub: hub-install
	@port=$${HUB_PORT:-$$(/usr/bin/python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')}; \
	  echo "JupyterHub: http://127.0.0.1:$$port/  logins: hub-instructor (formgrader), hub-student1..3; password: $$(cat build/hub/password)"; \
	  $(HUB_ENV) HUB_PORT=$$port HUB_API_PORT=$$((port+1)) HUB_PROXY_API_PORT=$$((port+2)) deploy/jupyterhub/deploy.sh start

hub-down:
	$(HUB_ENV) deploy/jupyterhub/deploy.sh down
