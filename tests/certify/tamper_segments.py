#!/usr/bin/env python3
"""Write a tampered copy of a segment event-order certificate (kvd-segment-event-order/1).

Usage: tamper_segments.py IN TAMPERING OUT
       tamper_segments.py --list

As tamper.py (same exit status, same determinism), with the tamperings that
make sense for a segment scene's certificate:

  swap-order, claim-equal, drop-certificate, drop-event
                     as in tamper.py. drop-event merges the intervals around
                     the deleted batch under the earlier one's active list,
                     whose certificates fail inside the merged interval.
  move-root          the first event whose factor has another distinct real
                     root gets an isolating interval of that root (the next
                     larger one, else the next smaller one); if no event's
                     factor has a second real root, the first event's
                     interval is shifted to [hi + 1, hi + 2], which holds no
                     root.
  change-polynomial  the constant term of the first polynomial of a
                     certificate changes by +1, in the lowest-id certificate
                     with a polynomial that no event refers to, else in the
                     first certificate with a polynomial.
  flip-sign          the sign of the first certificate with a polynomial is
                     negated.
  move-endpoint      the scene moves the first point of the first x order
                     with a polynomial whose first point is an endpoint, by
                     +1 in x (the rest position, or the constant term of X in
                     an "endpoints" motion): its polynomial is no longer the
                     scene's.
"""

import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from tamper import NotApplicable, Sturm, claim_equal, drop_certificate, drop_event, fmt, main, rat, swap_order


def move_root(doc):
    ev = doc["events"]
    if not ev:
        raise NotApplicable("no events")
    for i, e in enumerate(ev):
        st = Sturm([rat(c) for c in doc["certificates"][e["certificate"]]["polynomials"][e["factor"]]])
        roots = st.roots()
        if len(roots) < 2:
            continue
        lo, hi = rat(e["interval"][0]), rat(e["interval"][1])
        k = next(j for j, (a, b) in enumerate(roots) if max(a, lo) <= min(b, hi)
                 and st.count_closed(max(a, lo), min(b, hi)) == 1)
        a, b = roots[k + 1 if k + 1 < len(roots) else k - 1]
        e["interval"] = [fmt(a), fmt(b)]
        return "event %d: interval of another root [%s, %s]" % (i, fmt(a), fmt(b))
    e = ev[0]
    hi = rat(e["interval"][1])
    e["interval"] = [fmt(hi + 1), fmt(hi + 2)]
    return "event 0: interval shifted to [%s, %s], no root" % (fmt(hi + 1), fmt(hi + 2))


def with_polynomial(doc):
    return [i for i, c in enumerate(doc["certificates"]) if c["polynomials"]]


def change_polynomial(doc):
    cands = with_polynomial(doc)
    if not cands:
        raise NotApplicable("no certificate has a polynomial")
    used = {e["certificate"] for e in doc["events"]}
    cid = next((i for i in cands if i not in used), cands[0])
    p = doc["certificates"][cid]["polynomials"][0]
    p[0] = fmt(rat(p[0]) + 1)
    return "certificate %d: constant term of its first polynomial + 1" % cid


def flip_sign(doc):
    cands = with_polynomial(doc)
    if not cands:
        raise NotApplicable("no certificate has a polynomial")
    c = doc["certificates"][cands[0]]
    c["sign"] = -c["sign"]
    return "certificate %d: sign %d -> %d" % (cands[0], -c["sign"], c["sign"])


def move_endpoint(doc):
    for cid in with_polynomial(doc):
        c = doc["certificates"][cid]
        name = c["points"][0]
        if c["kind"] != "x_order" or "x" in name:
            continue
        s, k = (int(x) for x in name[1:].split("."))
        seg = doc["scene"]["segments"][s]
        motion = seg.get("motion") or {}
        if "endpoints" in motion:
            X = motion["endpoints"][k][0]
            X = list(X) if isinstance(X, list) else [X]
            X[0] = fmt(rat(str(X[0])) + 1)
            motion["endpoints"][k][0] = X
        else:
            seg["endpoints"][k][0] = fmt(rat(str(seg["endpoints"][k][0])) + 1)
        return "scene: endpoint %s moved by +1 in x; certificate %d is no longer the scene's" % (name, cid)
    raise NotApplicable("no x order with a polynomial starts with an endpoint")


ACTIONS = {"swap-order": swap_order, "move-root": move_root, "claim-equal": claim_equal,
           "drop-certificate": drop_certificate, "drop-event": drop_event, "change-polynomial": change_polynomial,
           "flip-sign": flip_sign, "move-endpoint": move_endpoint}

if __name__ == "__main__":
    sys.exit(main(sys.argv, ACTIONS, __doc__))
