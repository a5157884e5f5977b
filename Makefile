# Two commands on a fresh machine: `make lab` opens the configurator notebook,
# `make test` runs the whole suite. Both create .venv and (re)install the package with
# its dev and lab extras (JupyterLab itself is the `lab` extra) whenever pyproject.toml
# changes.

PYTHON ?= python3
VENV ?= .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed
NOTEBOOK_DIRS := $(wildcard notebooks course)

.PHONY: lab test lint bench venv clean

$(STAMP): pyproject.toml
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e ".[dev,lab]"
	touch $(STAMP)

venv: $(STAMP)

# Jupyter refuses to run as root unless told to (containers often are root).
ROOT_FLAG := $(if $(filter 0,$(shell id -u)),--allow-root,)

lab: $(STAMP)
	$(BIN)/jupyter lab $(ROOT_FLAG) notebooks/configurator.ipynb

# A third convenience, for students who don't code: the configurator alone in Voilà, on
# http://127.0.0.1:$(APP_PORT) and offline. app/serve.py is Voilà with a classroom's locks
# (token, XSRF, Host check, kernels per client); it runs in app/ to read app/voila.json
# (settings explained in docs/app.md); JUPYTER_PATH lets it find the app's template.
APP_PORT ?= 8866

.PHONY: app

app: $(STAMP)
	test -x $(BIN)/voila || $(BIN)/python -m pip install --quiet -e ".[app]"
	cd app && JUPYTER_PATH=$(CURDIR)/app/jupyter $(abspath $(BIN))/python serve.py configurator.ipynb --port=$(APP_PORT)

lint: $(STAMP)
	$(BIN)/ruff check .
	$(BIN)/ruff format --check .
	$(BIN)/mypy

# One pytest run: unit tests, doctests of the package, and every notebook (nbmake).
test: lint
	MPLBACKEND=Agg ROBOTCONF_FAST=1 $(BIN)/python -m pytest --nbmake robotconf tests $(NOTEBOOK_DIRS)

# A browser-only classroom: a JupyterLite site in dist/lite to publish as static files
# (docs/lite.md). lite/build.py installs the site's build tools into their own venv.
LITE_OUT ?= dist/lite

.PHONY: lite test-lite

lite: $(STAMP)
	$(BIN)/python lite/build.py --out $(LITE_OUT)

# Only the site's checks, against the site `make lite` just built (`make test` runs them
# too, on a site it builds in a temporary folder).
test-lite: lite
	ROBOTCONF_LITE_SITE=$(abspath $(LITE_OUT)) $(BIN)/python -m pytest tests/test_lite.py tests/browser/test_lite_browser.py

# A class on one computer: JupyterHub with configurable-http-proxy (from npm, pinned in
# hub/package-lock.json) and a separate student environment, robotconf with JupyterLab and
# no teacher tools (docs/hub.md). `make hub-env` only installs them (the hub browser test
# calls it); both live in build/hub/ and are redone when their pins change.
HUB_BUILD ?= build/hub
HUB_VENV := $(HUB_BUILD)/student-venv
HUB_STAMP := $(HUB_VENV)/.installed
HUB_PROXY := $(HUB_BUILD)/node_modules/.bin/configurable-http-proxy
HUB_PORT ?= 8000

.PHONY: hub hub-env

$(HUB_STAMP): pyproject.toml hub/overrides.json
	test -x $(HUB_VENV)/bin/python || $(PYTHON) -m venv $(HUB_VENV)
	$(HUB_VENV)/bin/python -m pip install --quiet --upgrade pip
	$(HUB_VENV)/bin/python -m pip install --quiet -e ".[hub]"
	# JupyterLab's settings for every student: no news prompt, no update checks.
	mkdir -p $(HUB_VENV)/share/jupyter/lab/settings
	cp hub/overrides.json $(HUB_VENV)/share/jupyter/lab/settings/overrides.json
	touch $(HUB_STAMP)

$(HUB_PROXY): hub/package.json hub/package-lock.json
	mkdir -p $(HUB_BUILD)
	cp hub/package.json hub/package-lock.json $(HUB_BUILD)/
	cd $(HUB_BUILD) && npm ci --no-audit --no-fund --loglevel=error
	touch $(HUB_PROXY)

hub-env: $(HUB_STAMP) $(HUB_PROXY)

hub: hub-env
	@password=$${ROBOTCONF_HUB_PASSWORD:-$$($(PYTHON) -c "import secrets; print(secrets.token_urlsafe(9))")}; \
	echo "Students ada and alan log in at http://127.0.0.1:$(HUB_PORT)/ with the password $$password"; \
	ROBOTCONF_HUB_PORT=$(HUB_PORT) ROBOTCONF_HUB_PASSWORD=$$password \
		$(HUB_VENV)/bin/jupyterhub -f hub/jupyterhub_config.py

bench: $(STAMP)
	for script in benchmarks/bench_*.py; do $(BIN)/python $$script || exit 1; done

clean:
	rm -rf $(VENV) .pytest_cache .ruff_cache build *.egg-info
