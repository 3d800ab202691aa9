"""Write docs/rules.md from the rule modules (a test fails when it is stale)."""

from pathlib import Path

from achslint.docs import rules_markdown

TARGET = Path(__file__).resolve().parents[1] / "docs" / "rules.md"

if __name__ == "__main__":
    TARGET.parent.mkdir(exist_ok=True)
    TARGET.write_text(rules_markdown(), encoding="utf-8")
    print(f"wrote {TARGET}")
