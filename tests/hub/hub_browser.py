"""The course through the hub's pages in Debian's chromium (Playwright): a student logs in, fetches from
the Assignments tab, writes the solution, runs the sample check, submits, later fetches feedback;
the instructor releases, collects, autogrades and returns feedback with formgrader's buttons.

Used by tests/hub/test_hub.py (one browser student beside the two that use the HTTP APIs)::

    with student_browser() as browser:
        s = BrowserStudent(browser, hub, hub_session.STUDENTS[2], SHOTS)
        s.log_in(); s.fetch("delaunay"); s.write_and_check("delaunay", code); s.submit("delaunay")

Everything is done as a student does it: the hub's login form and *Start My Server*;
**Nbgrader → Assignment List**;
the *Fetch* and *Submit* buttons; the notebook opened from the file browser's URL; the first
solution cell's text replaced by typing into its editor (Ctrl+A, then the code inserted as one
input, as a paste does); Ctrl+S; the check cell run with Shift+Enter, and its table read from the
page. Each step waits on the page's state, never on a fixed sleep; each leaves a screenshot in
``shots`` (the deployment guide's pictures come from there).
"""
from __future__ import annotations

import json
import pwd
import re
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "browser"))
from labdriver import CHROMIUM, launch_browser  # noqa: E402,F401 - Debian chromium under Playwright

student_browser = launch_browser
"""Headless Debian chromium (Playwright never downloads a browser here)."""


class HubTab:
    """One account's tab on the hub: its login and its screenshots."""

    def __init__(self, browser, hub, name: str, shots: Path) -> None:
        self.hub, self.name, self.shots = hub, name, Path(shots)
        self.shots.mkdir(parents=True, exist_ok=True)
        self.page = browser.new_page(viewport={"width": 1400, "height": 900})
        self.base = f"{hub.url}/user/{name}"

    def shot(self, what: str) -> Path:
        path = self.shots / f"hub-{what}.png"
        self.page.screenshot(path=str(path))
        return path

    def dialogs(self) -> str:
        """The text of every dialog open in the page (JupyterLab's error dialogs, formgrader's
        modals), for a failure's report."""
        try:
            found = self.page.locator(".jp-Dialog, .modal.in, .modal.show")
            return "\n".join(found.nth(i).inner_text(timeout=2_000)[:2000] for i in range(found.count()))
        except Exception as e:                       # the page itself may be gone
            return f"(no dialogs read: {e})"

    def log_in(self) -> None:
        """The hub's login form; the hub starts the server and lands in JupyterLab."""
        page = self.page
        page.goto(self.hub.url + "/hub/login")
        page.fill("input[name=username]", self.name)
        page.fill("input[name=password]", self.hub.password)
        self.shot("login")
        page.click("#login_submit, [type=submit]")
        start = page.get_by_role("link", name="Start My Server").or_(page.get_by_role("button", name="Start My Server"))
        start.first.wait_for(timeout=60_000)            # the hub's home page
        self.shot("home")
        start.first.click()
        page.wait_for_url(re.compile(rf"/user/{re.escape(self.name)}/lab"), timeout=180_000)
        page.locator(".lm-MenuBar-itemLabel", has_text="Nbgrader").wait_for(timeout=120_000)

class BrowserStudent(HubTab):
    """A student's tab: the Assignments tab, the notebook, the sample check."""

    def open_assignments(self):
        """Nbgrader → Assignment List (or its tab when it is open already); the panel's locator."""
        page = self.page
        panel = page.locator("#nbgrader-assignment-list")
        if panel.count() and panel.is_visible():
            return panel
        tab = page.locator(".lm-TabBar-tab", has_text="Assignments")
        if tab.count():
            tab.first.click()
        else:
            page.locator(".lm-MenuBar-itemLabel", has_text="Nbgrader").click()
            page.locator(".lm-Menu-itemLabel", has_text="Assignment List").click()
        panel.wait_for(timeout=60_000)
        return panel

    def _row(self, panel, listing: str, assignment: str):
        """The row of ``assignment`` (its name cell, exactly: every row also says "delaunay-course")."""
        name = self.page.locator(".item_name", has_text=re.compile(rf"^\s*{re.escape(assignment)}\s*$"))
        return panel.locator(f"#{listing} .list_item").filter(has=name).first

    def fetch(self, assignment: str) -> None:
        panel = self.open_assignments()
        row = self._row(panel, "released_assignments_list", assignment)
        row.wait_for(timeout=60_000)
        self.shot(f"assignments-{assignment}")
        row.get_by_role("button", name="Fetch").click()
        self._row(panel, "fetched_assignments_list", assignment).wait_for(timeout=120_000)

    def write_and_check(self, assignment: str, code: str, expect: str) -> str:
        """Open the fetched notebook, type ``code`` into the first solution cell, save, run the
        sample check cell; return the check's output text once it contains ``expect``."""
        page = self.page
        page.goto(f"{self.base}/lab/tree/{assignment}/{assignment}.ipynb")
        # the notebook shown now (an earlier assignment's notebook stays open in a hidden tab)
        cells = page.locator(".jp-NotebookPanel:not(.lm-mod-hidden) .jp-Notebook .jp-CodeCell")
        solution = cells.filter(has_text="YOUR CODE HERE").first
        solution.wait_for(timeout=120_000)
        solution.locator(".cm-content").first.click()
        page.keyboard.press("Control+a")
        page.keyboard.insert_text(code)
        page.keyboard.press("Escape")
        page.keyboard.press("Control+s")
        self.wait_saved(assignment, code)
        check = cells.filter(has_text="%check_samples").first
        for _ in range(40):                            # below a long solution: scroll until it is shown
            if check.locator(".cm-content").first.is_visible():
                break
            page.mouse.move(700, 500)
            page.mouse.wheel(0, 600)
            page.wait_for_timeout(100)
        check.locator(".cm-content").first.click()
        page.keyboard.press("Shift+Enter")
        output = check.locator(".jp-OutputArea-output").first
        page.wait_for_function("([el, want]) => el.innerText.includes(want)",
                               arg=[check.element_handle(), expect], timeout=300_000)
        check.scroll_into_view_if_needed()
        self.shot(f"check-{assignment}")
        return output.inner_text()

    def wait_saved(self, assignment: str, code: str, timeout: float = 60) -> None:
        """Wait until the notebook file in the student's home holds ``code`` in a code cell.

        The file is read from the disk, where the sample check and Submit read it. (Polling the
        contents API during saves once lost a student's save here, with jupyter_server 2.21's own
        save; the course's jupyter_server_config.py fixed that, tests/hub/test_saves.py.) A dialog
        in the page (a failed save) fails at once, with its text.
        """
        path = Path(pwd.getpwnam(self.name).pw_dir) / assignment / f"{assignment}.ipynb"
        want = code.strip()
        deadline = time.monotonic() + timeout
        while True:
            try:
                cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
                if any(c["cell_type"] == "code" and "".join(c["source"]).strip() == want for c in cells):
                    return
            except (OSError, ValueError, KeyError):   # not there yet, or being written
                pass
            if self.page.locator(".jp-Dialog").count():
                raise AssertionError(f"{self.name}: saving {path.name}: {self.dialogs()}")
            if time.monotonic() > deadline:
                raise AssertionError(f"{self.name}: {path} does not hold the typed code {timeout:.0f} s after Ctrl+S")
            time.sleep(0.25)

    def submit(self, assignment: str) -> None:
        panel = self.open_assignments()
        page = self.page
        panel.locator("#refresh_assignments_list").first.click()
        row = self._row(panel, "fetched_assignments_list", assignment)
        row.wait_for(timeout=60_000)
        row.get_by_role("button", name="Submit").click()
        self._row(panel, "submitted_assignments_list", assignment).wait_for(timeout=120_000)
        page.wait_for_timeout(200)
        self.shot(f"submitted-{assignment}")

    def fetch_feedback(self, assignment: str) -> str:
        """Fetch Feedback in the Assignments tab, then open the feedback's HTML; return its text."""
        panel = self.open_assignments()
        page = self.page
        panel.locator("#refresh_assignments_list").first.click()
        row = self._row(panel, "submitted_assignments_list", assignment)
        button = row.get_by_role("button", name="Fetch Feedback")
        button.wait_for(timeout=120_000)
        button.click()
        link = row.get_by_text("(view feedback)")
        link.wait_for(timeout=120_000)
        self.shot(f"feedback-{assignment}")
        link.click()                                   # the file browser goes to the feedback folder
        page.locator(".jp-BreadCrumbs", has_text="feedback").wait_for(timeout=60_000)
        files = page.evaluate("""async ([base, a]) => {
            const xsrf = (document.cookie.match(/(?:^|; )_xsrf=([^;]*)/) || [])[1] || '';
            const get = async p => (await (await fetch(`${base}/api/contents/${p}`,
                {headers: {'X-XSRFToken': decodeURIComponent(xsrf)}})).json()).content;
            const out = [];
            for (const stamp of await get(`${a}/feedback`))
                for (const f of await get(stamp.path)) if (f.name.endsWith('.html')) out.push(f.path);
            return out; }""", [self.base, assignment])
        if not files:
            raise AssertionError(f"{self.name}: no feedback HTML under {assignment}/feedback")
        page.goto(f"{self.base}/files/{files[0]}")
        page.wait_for_load_state()
        self.shot(f"feedback-page-{assignment}")
        text = page.inner_text("body")
        page.goto(f"{self.base}/lab")
        return text


class BrowserInstructor(HubTab):
    """The instructor's tab: formgrader's own pages (``/formgrader/manage_assignments`` and
    ``manage_submissions/<id>``), whose buttons are icons in table columns; each click waits for
    formgrader's "Success" dialog (an error dialog fails with its text) and closes it with *OK*."""

    def _click(self, path: str, row_cell: str, name: str, column: str, what: str) -> None:
        page = self.page
        if not page.url.endswith(path):
            page.goto(f"{self.base}/formgrader/{path}")
        cell = page.locator(f"td.{row_cell}", has_text=re.compile(rf"^\s*{re.escape(name)}\s*$"))
        row = page.locator("tr").filter(has=cell).first
        button = row.locator(f"td.{column} a").first
        button.wait_for(timeout=60_000)
        button.click()
        done = page.locator("#success-modal, #error-modal").first
        done.wait_for(timeout=600_000)
        if page.locator("#error-modal").count():
            raise AssertionError(f"formgrader: {what} of {name}: {page.locator('#error-modal').inner_text()[:3000]}")
        self.shot(what)
        done.get_by_role("button", name="OK").click()
        page.locator("#success-modal").wait_for(state="detached", timeout=30_000)

    def assignment(self, assignment: str, column: str) -> None:
        """A button of the assignment's row in Manage Assignments: assign (Generate), release, collect,
        generate-feedback, release-feedback."""
        self._click("manage_assignments", "name", assignment, column, f"formgrader-{column}-{assignment}")

    def autograde(self, assignment: str, student: str) -> None:
        """Autograde (the flash icon) of one student's row in the assignment's submissions."""
        self._click(f"manage_submissions/{assignment}", "student-id", student, "autograde",
                    f"formgrader-autograde-{assignment}-{student}")
