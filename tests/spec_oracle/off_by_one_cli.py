"""A deliberately wrong command line, for the test that test_agreement.py
can fail: it runs the real one (the first argument) and adds one to the
reflections of every `yes` it prints in JSON."""
import json
import subprocess
import sys

run = subprocess.run(sys.argv[1:], stdin=sys.stdin, capture_output=True, text=True)
try:
    answer = json.loads(run.stdout)
except json.JSONDecodeError:
    sys.stdout.write(run.stdout)
else:
    if answer.get("answer") == "yes":
        answer["reflections"] = answer["reflections"] + 1
        for target in answer.get("targets", []):
            if target["answer"] == "yes":
                target["reflections"] += 1
    print(json.dumps(answer))
sys.stderr.write(run.stderr)
sys.exit(run.returncode)
