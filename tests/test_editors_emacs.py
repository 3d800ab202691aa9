"""Emacs with eglot, configured with the README's snippet, edits a real list through `achslint server`
(issue 28 item 1): findings, hover, completion accepted, a quick fix, formatting, the outline, go to
definition, an edit and the findings after it, a TwinCAT export's machine findings.

Emacs runs in batch mode: the driver below loads the snippet, opens the list as `find-file` does and runs
what the command loop runs after a command (`post-command-hook`: eglot-ensure connects there), then calls the
commands a user would (completion-at-point, eglot-code-actions taking the offered default,
eglot-format-buffer, imenu, xref-find-definitions). Run with `pytest -m slow`."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest

from achslint.fmt import format_bytes

from .editors import environment, installed, lint_codes, machine, snippet

pytestmark = pytest.mark.slow
LOAD_PACKAGES = ["--eval", "(progn (require (quote package)) (package-initialize))"]  # eglot from ELPA too

DRIVER = r"""
(require 'cl-lib)
(require 'subr-x)
(setq make-backup-files nil auto-save-default nil create-lockfiles nil)
(defun step (what) (princ (format "step: %s\n" what)))
(defun idle ()  ; what Emacs runs when the user stops typing (batch mode never is idle)
  (dolist (timer (copy-sequence timer-idle-list)) (timer-event-handler timer)))
(defun wait-until (pred what &optional seconds)
  (let ((deadline (+ (float-time) (or seconds 30))))
    (while (and (not (funcall pred)) (< (float-time) deadline))
      (idle)
      (accept-process-output nil 0.1))
    (or (funcall pred) (error "no %s" what))))
(defun after-command () (run-hooks 'post-command-hook))  ; what the command loop runs after a command
(defun codes ()
  (delete-dups
   (cl-loop for d in (flymake-diagnostics)
            for spec = (cdr (assoc 'eglot-lsp-diag (flymake-diagnostic-data d)))
            when (plist-get spec :code) collect (plist-get spec :code))))
(defun line-text (n) (save-excursion (goto-char (point-min)) (forward-line n)
                                     (buffer-substring-no-properties (line-beginning-position) (line-end-position))))
(defun goto-text (text &optional shift)
  (goto-char (point-min)) (search-forward text) (goto-char (+ (match-beginning 0) (or shift 0))))

(find-file (getenv "AXIS"))
(after-command)
(step (format "mode %s" major-mode))
(wait-until (lambda () (eglot-current-server)) "eglot connection")
(let ((expected (split-string (getenv "EXPECTED") ",")))
  (wait-until (lambda () (equal (sort (codes) #'string<) (sort (copy-sequence expected) #'string<)))
              (format "findings %S (have %S)" expected (codes))))
(step "findings")

(goto-text "getriebe[0].vb_refmax" 3)
(defvar hover-info nil)
(eglot-hover-eldoc-function (lambda (info &rest _) (setq hover-info info)))  ; what eldoc shows
(wait-until (lambda () hover-info) "hover")
(unless (and (string-match-p "P-AXIS-00219" hover-info) (string-match-p "100 mm/s" hover-info))
  (error "hover: %s" hover-info))
(step "hover")

(goto-text "\nEnde" 1)
(insert "getriebe[0].vb_refl\n")
(forward-line -1) (end-of-line)
(completion-at-point)
(after-command)
(unless (equal (line-text (1- (line-number-at-pos))) "getriebe[0].vb_reflow")
  (error "completion gave %S" (line-text (1- (line-number-at-pos)))))
(step "completion")
(insert " 5000")
(after-command)
(insert "\ngetriebe[0].vb_nonsense  1")
(after-command)
(flymake-start)  ; flymake's idle timer, which batch mode does not run
(wait-until (lambda () (member "LIS101" (codes))) "LIS101 after the edit")
(delete-region (line-beginning-position) (line-end-position)) (delete-char -1)
(after-command)
(flymake-start)
(wait-until (lambda () (not (member "LIS101" (codes)))) "LIS101 gone")
(step "edit")

(goto-text "CNC_CONROLLED")
(let ((last-nonmenu-event 13))  ; invoked from the keyboard: the choice is read in the minibuffer
  (cl-letf (((symbol-function 'completing-read)  ; the user takes the offered default
             (lambda (_prompt _items &optional _pred _req _init _hist default &rest _) default)))
    (eglot-code-actions (line-beginning-position) (line-end-position) nil t)))
(after-command)
(unless (string-match-p "homing_type +CNC_CONTROLLED" (buffer-string)) (error "the quick fix was not applied"))
(flymake-start)  ; flymake's idle timer, which batch mode does not run
(wait-until (lambda () (not (member "LIS203" (codes)))) "LIS203 gone")
(step "quick fix")

(save-buffer)
(eglot-format-buffer)
(save-buffer)
(step "formatting")

(defun names (index)  ; every entry's name, at any depth (eglot 1.9 groups them by symbol kind first)
  (cl-loop for entry in index
           append (cons (car entry) (and (consp (cdr entry)) (listp (cddr entry)) (names (cdr entry))))))
(let ((found (names (funcall imenu-create-index-function))))
  (unless (cl-every (lambda (name) (member name found)) '("kopf" "getriebe[0]" "Ende" "achs_nr"))
    (error "outline: %S" found)))
(step "outline")

(goto-text "P-AXIS-00212.0" 2)
(let ((xref-prompt-for-identifier nil))
  (call-interactively #'xref-find-definitions))
(unless (string-prefix-p "getriebe[0].dynamik.vb_max" (line-text (1- (line-number-at-pos))))
  (error "definition went to %S" (line-text (1- (line-number-at-pos)))))
(step "definition")

(find-file (getenv "XML"))
(after-command)
(step (format "mode %s" major-mode))
(wait-until (lambda () (eglot-current-server)) "eglot connection for the export")
(flymake-start)
(wait-until (lambda () (member "LIS501" (codes)))
            (format "LIS501 in the export (have %S, flymake %S)" (codes) (flymake-running-backends)))
(step "export")
(kill-emacs 0)
"""


def test_emacs_eglot_with_the_readme_configuration(tmp_path: Path) -> None:
    program = installed(
        "emacs",
        [["apt-get", "install", "-y", "-qq", "emacs-nox", "elpa-eglot"]],
        "Emacs cannot be installed here (apt-get install emacs-nox elpa-eglot failed)",
    )
    files = machine(tmp_path / "machine")
    home = tmp_path / "home"
    home.mkdir()
    config = home / "achslint.el"
    config.write_text(snippet("elisp"), encoding="utf-8")  # the README's configuration, verbatim
    driver = home / "driver.el"
    driver.write_text(DRIVER, encoding="utf-8")
    probe = subprocess.run(
        [
            program,
            "--batch",
            "-q",
            "--eval",
            "(progn (require 'package) (package-initialize) (require 'eglot))",
        ],
        capture_output=True,
        text=True,
        env=environment(home),
    )
    if probe.returncode != 0:
        reason = "eglot is not installed for this Emacs (Emacs 28 needs the elpa-eglot package)"
        print(f"SKIPPED: {reason}")
        pytest.skip(reason)
    env = environment(home)
    env.update(
        AXIS=str(files["axis"]), XML=str(files["xml"]), EXPECTED=",".join(sorted(lint_codes(files["axis"])))
    )
    run = subprocess.run(
        [program, "--batch", "-q", *LOAD_PACKAGES, "-l", str(config), "-l", str(driver)],
        capture_output=True,
        text=True,
        env=env,
        cwd=files["axis"].parent,
        timeout=300,
    )
    steps = [line for line in run.stdout.splitlines() if line.startswith("step: ")]
    assert run.returncode == 0, f"{steps}\n{run.stderr[-3000:]}"
    assert steps[-1] == "step: export" and "step: mode achsmds-mode" in steps
    formatted, _ = format_bytes(files["axis"].read_bytes(), str(files["axis"]))
    assert files["axis"].read_bytes() == formatted  # eglot-format-buffer wrote what `achslint fmt` writes
    assert b"getriebe[0].vb_reflow" in formatted and b"CNC_CONTROLLED" in formatted
