#!/usr/bin/env bash
# The fault simulation's own mutation score (docs/testing.md, "Mutation
# test"): each of the one-line mutations of the safety logic below, one at a
# time, is applied to its file, only the simulation test is rebuilt
# (andros_simulation_tests in $BUILD_DIR, default build/, configured by
# scripts/build.sh), its seeds run with every failing seed counted
# (ANDROS_SIM_COUNT_ALL=1), and the file is put back. Prints, per mutation,
# how many seeds of how many caught it. The simulation alone should catch
# every one, each by many seeds.
#
# Not part of scripts/test.sh: 62 rebuilds and 63 runs of 10,000 seeds.
# ANDROS_SIM_SCRIPTS=N runs N seeds instead; MUTATIONS="1 5" only those.
# Exit 1 when a mutation is caught by no seed, when the unmutated code fails
# a seed, or when a mutation's text is no longer in its file (the code moved:
# update its line here). A run cut short puts the file back, but an object
# compiled from the mutation may then be newer than it: touch the mutated files
# before the next build.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${BUILD_DIR:-build}
seeds=${ANDROS_SIM_SCRIPTS:-10000}

# name | file | perl substitution (applied to the whole file: -0)
mutations=(
  "a stop reset 400 ms before the full hold|src/run/stop_buttons.cpp|s/now_ms - \*r.hold_since < hold_ms_\)/now_ms - *r.hold_since < hold_ms_ - 400)/"
  "a panic latch cleared without the full release|src/run/deadman.cpp|s/!past\(lowest, mapping::kDeadmanFullyReleased\)/!past(lowest, *panic_)/"
  "neutral drive and pivot taken from the trim|src/mapping/safety.cpp|s/if \(!ctx.enabled\) v = protocol::kNeutralCentre;/if (!ctx.enabled) v = static_cast<std::uint8_t>(ctx.center);/"
  "the opposing-pair interlock removed|src/mapping/safety.cpp|s/asked\[\*partner\] != 0\) state.values\[i\] = 0;/asked[*partner] != 0 \&\& false) state.values[i] = 0;/"
  "the rest rule skipped when a layer is left|src/mapping/safety.cpp|s/const bool changed = edge \|\| was == before.end\(\) \|\| !same_bindings\(was->second, readers\);/const bool changed = edge || (layer >= layer_ \&\& (was == before.end() || !same_bindings(was->second, readers)));/"
  "a resume (SIGCONT) while enabled without a rebase|src/run/operating_state.cpp|s/settle\(S::kEnabled, E::kResume, true\)/settle(S::kEnabled, E::kResume, false)/"
  "the engine stepped before the machine read the tick's facts|src/run/bridge.cpp|s/(  act\(machine_.on\(facts\), false\);\n)((?:.*\n){3})/\$2\$1/"
  "the deadman touched during a reset hold ignored|src/run/stop_buttons.cpp|s/ \|\| deadman_touched;/;/"
  "a deadman held at connect taken for a fresh press|src/run/deadman.cpp|s/input.button\(\*key_\).presses > base_/input.button(*key_).presses >= base_/"
  "a weapon armed without its arming input held|src/mapping/engine_bindings.cpp|s/const bool arm = b.arm && held\(input, \*b.arm\) && c_.rest.consent\(\);/const bool arm = b.arm \&\& c_.rest.consent();/"
  "a link regained without a rebase|src/run/operating_state.cpp|s/settle\(S::kNoLink, E::kLinkUp, true\)/settle(S::kNoLink, E::kLinkUp, false)/"
  "the enable timeout never falls due|src/run/drive_guard.cpp|s/ && timed_out\(now_ms\)\)/ \&\& false \&\& timed_out(now_ms))/"
  "a stop button held does not hold off a reset|src/run/stop_buttons.cpp|s/out.pressed.any\(\) \|\| down\(op, operator_\) \|\| down\(sup, supervisor_\)/out.pressed.any()/"
  "issue 33: a stop button let go and held 2 s resets|src/run/stop_buttons.cpp|s/supervisor_reset_.keys = keys_of\(mapping.supervisor->reset\);/supervisor_reset_.keys = {mapping.supervisor->stop.key};/; s/operator_reset_.keys = keys_of\(mapping.stop_reset\);/if (mapping.estop) operator_reset_.keys = {mapping.estop->key};/; s/const bool blocked = out.pressed.any\(\) \|\| down\(op, operator_\) \|\| down\(sup, supervisor_\) \|\| deadman_touched;/const bool blocked = deadman_touched;/; s/return fresh \|\| down\(pad, b\);/return fresh;/"
  "a stop button held stops only when pressed|src/run/stop_buttons.cpp|s/return fresh \|\| down\(pad, b\);/return fresh;/"
  "another pad of the role resets the stop|src/run/operating_state.cpp|s/return pad == stopper_pad_;/return true;/"
  "the operator resets any stop, the supervisor's too|src/run/operating_state.cpp|s/if \(by == StopBy::kOperator && stopped_by_ == StopBy::kSupervisor\) return false;/if (by == StopBy::kOperator) return true;/"
  "the supervisor's stop button ignored|src/run/stop_buttons.cpp|s/const bool by_supervisor = take\(input.supervisor\(\), supervisor_\);/const bool by_supervisor = take(input.supervisor(), supervisor_) \&\& false;/"
  "issue 35: the enable timeout's noise band set to 0|src/run/drive_guard.cpp|s/constexpr int kActivityBand = 1024;/constexpr int kActivityBand = 0;/"
  "issue 35: motion sent to a stalled server|include/andros/link/link_status.hpp|s/return state == LinkState::kUp && far_end_reading;/return state == LinkState::kUp;/"
  "issue 35: dip-switch codes 0x80 and above made others|src/base/text.cpp|s/return static_cast<std::uint8_t>\(\*value\);/return static_cast<std::uint8_t>(*value \& 0x7F);/"
  "the checksum sent high byte first|src/protocol/frame.cpp|s/frame\[34\] = static_cast<std::uint8_t>\(sum & 0xFF\);/frame[34] = static_cast<std::uint8_t>(sum >> 8);/"
  "a data byte's high digit shifted 3, not 4|src/protocol/frame.cpp|s/hex_digit\(data\[i\] >> 4U\)/hex_digit(data[i] >> 3U)/"
  "the builder leaves byte 15 out|src/protocol/frame.cpp|s/  data\[kTrailerByte\] = kTrailerValue;\n//"
  "the frame gate reads the code as 7 bits|src/run/frame_gate.cpp|s/if \(data\[protocol::kCodeByte\] != rules_.code\)/if ((data[protocol::kCodeByte] \& 0x7F) != rules_.code)/"
  "a toggled layer kept past the deadman|src/mapping/engine.cpp|s/if \(!enabled\) c_.toggled_layer = -1;/if (false) c_.toggled_layer = -1;/"
  "toggles kept past the deadman|src/mapping/engine.cpp|s/    clear_toggles\(\);  \/\/ releasing the deadman/    \/\/ releasing the deadman/"
  "a suspend without its neutral frames|src/run/operating_state.cpp|s/\(to == S::kSuspended \|\| to == S::kReloading/(to == S::kReloading/"
  "two neutral frames, not three|include/andros/run/bridge.hpp|s/int shutdown_frames = 3;/int shutdown_frames = 2;/"
  "a deadman let go between two ticks not seen|src/run/deadman.cpp|s/if \(key_->is_button\(\)\) return input.button\(\*key_\).releases > releases_seen_;/if (key_->is_button()) return false;/"
  "the panic point ignored|src/run/deadman.cpp|s/if \(panic\(input\)\) return DeadmanState::kPastPanic;/if (false \&\& panic(input)) return DeadmanState::kPastPanic;/"
  "a trigger held at connect taken for a fresh press|src/run/deadman.cpp|s/input.button\(\*key_\).presses > base_ : released_seen_;/input.button(*key_).presses > base_ : true;/"
  "a link lost and back between frames not answered|src/run/bridge_requests.cpp|s/new link.\n        link_changed\(false, Who::kScript\);/new link./"
  "a reload without a rebase|src/run/operating_state.cpp|s/settle\(S::kReloading, E::kReloadDone, true\)/settle(S::kReloading, E::kReloadDone, false)/"
  "the supervisor's reset without a rebase|src/run/operating_state.cpp|s/settle\(S::kStopped, E::kSupervisorReset, true\)/settle(S::kStopped, E::kSupervisorReset, false)/"
  "presses made while not enabled replayed on enabling|src/mapping/engine.cpp|s/  for \(const auto key : buttons_\) c_.seen_presses\[key\] = input.button\(key\).presses;\n  last_ms_/  if (enabled) for (const auto key : buttons_) c_.seen_presses[key] = input.button(key).presses;\n  last_ms_/"
  "weapons fire without the supervisor's consent|include/andros/mapping/safety.hpp|s/return consent_ == ConsentState::kNotAsked \|\| consent_ == ConsentState::kGiven;/return true;/"
  "of a pair asked both, the first sent|src/mapping/safety.cpp|s/asked\[\*partner\] != 0\) state.values\[i\] = 0;/asked[*partner] != 0 \&\& *partner < i) state.values[i] = 0;/"
  "the frame gate keeps no selector in a neutral frame|src/run/frame_gate.cpp|s/return sig.kind == SignalKind::kSelector; \}/return sig.kind == SignalKind::kSelector \&\& false; }/"
  "the frame gate refuses a weapon while enabled|src/run/frame_gate.cpp|s/if \(!enabled\) return named\(i\) \+/if (enabled) return named(i) +/"
  "a fire button held when its weapon is armed fires|src/mapping/safety.cpp|s/  hold_back_fire_inputs\(input, layer, seen\);\n//"
  "a consent held since before the weapon became possible counts|src/mapping/safety.cpp|s/held_back = now.down \&\& !pressed_now;/held_back = !now.down \&\& !pressed_now;/"
  "a fire button held when the consent comes fires|src/mapping/safety.cpp|s/if \(!consent\(\) \|\| held_.contains\(arm\)/if (held_.contains(arm)/"
  "a speed level's change without the rest rule|src/mapping/engine_bindings.cpp|s/  c_.rest.rescale\(input, c_.layer\);\n//"
  "the speed level down from the slowest wraps to the fastest|src/mapping/engine_bindings.cpp|s/level -= std::min<std::size_t>\(level, new_presses\(input, scale.down->key\)\);/level = (level + count - new_presses(input, scale.down->key) % count) % count;/"
  "a new controller or a restart keeps the speed level|src/mapping/engine.cpp|s/  set_speed\(mapping_->scale.initial\);\n  if \(at_start_up\)/  if (at_start_up)/"
  "speed presses while not enabled step the level|src/mapping/engine.cpp|s/if \(enabled\) update_speed\(input\);/update_speed(input);/"
  "the frame gate lets an opposing pair through|src/run/frame_gate.cpp|s/if \(partner && \*partner > i && s.values\[i\] != 0 && s.values\[\*partner\] != 0\) \{/if (false) {/"
  "the frame gate lets drive or pivot off 128 through, not enabled|src/run/frame_gate.cpp|s/if \(sig.kind == SignalKind::kCentred && s.values\[i\] != protocol::kNeutralCentre\) \{/if (false) {/"
  "the frame gate lets a motion bit through, not enabled|src/run/frame_gate.cpp|s/&& !kept_in_neutral\(sig\) && s.values\[i\] != 0\) return/\&\& false) return/"
  "the frame gate lets a weapon through without --weapons|src/run/frame_gate.cpp|s/if \(!rules_.weapons\) return/if (false) return/"
  "the frame gate does not check the code|src/run/frame_gate.cpp|s/if \(data\[protocol::kCodeByte\] != rules_.code\) \{/if (false) {/"
  "the frame gate does not check the validation table|src/run/frame_gate.cpp|s/validation_errors\(data\); !errors.empty\(\)\)/validation_errors(data); false \&\& !errors.empty())/"
  "the TCP link's stall detection off|src/link/tcp_link.cpp|s/if \(now_ns - progress_.since_ns >= kTcpStallNs\) \{/if (false) {/"
  "a stall declared after 1 s, not 2|include/andros/link/tcp_link.hpp|s/kTcpStallNs = 2'000'000'000;/kTcpStallNs = 1'000'000'000;/"
  "frames never held back for the server's window|src/link/tcp_link.cpp|s/if \(unread > kTcpMaxUnreadBytes && now_ns - progress_.probe_ns < kTcpProbeNs\)/if (false)/"
  "a server that stalled trusted again on a new connection|src/link/tcp_link.cpp|s/progress_ = Progress\{.since_ns = now_ns\};/progress_ = Progress{.since_ns = now_ns};\n  suspect_ = false;/"
  "issue 35: the TCP link never says the server stalled|include/andros/link/tcp_link.hpp|s/return !suspect_; \}/return true; }/"
  "the back-off skipped after a failed attempt|src/link/reconnecting_link.cpp|s/(detail_ = why;\n  next_attempt_ns_ = now_ns)[^;]*;/\$1;/"
  "the back-off skipped after a loss|src/link/reconnecting_link.cpp|s/(retry_ms_ = min_retry_ms_;\n  next_attempt_ns_ = now_ns)[^;]*;/\$1;/"
  "the back-off never doubles|src/link/reconnecting_link.cpp|s/retry_ms_ = std::min\(retry_ms_ \* 2, max_retry_ms_\);/retry_ms_ = min_retry_ms_;/g"
  "the back-off reset by a connection lost within 5 s|src/link/reconnecting_link.cpp|s/if \(now_ns - up_since_ns_ >= kStableNs\) retry_ms_/retry_ms_/"
)

[[ -f $build_dir/CMakeCache.txt ]] || { echo "no build in $build_dir: run scripts/build.sh first" >&2; exit 1; }
backup=$(mktemp -d)
restore() {
  for f in "$backup"/*; do
    [[ -e $f ]] || continue
    cp "$f" "$(tr '%' '/' <<<"${f##*/}")"
  done
  rm -rf "$backup"
}
trap restore EXIT

# A mutation may leave a parameter or a helper unused: its build must not
# fail on a warning (a tree that CI=true scripts/build.sh configured makes
# warnings errors; scripts/build.sh sets it again each time).
cmake -S . -B "$build_dir" -DANDROS_WERROR=OFF >/dev/null
run_simulation() {  # prints how many seeds broke a rule; fails, printing nothing, when the build fails
  cmake --build "$build_dir" --target andros_simulation_tests >/dev/null || return 1
  ANDROS_SIM_COUNT_ALL=1 ANDROS_SIM_MAX_REPORTED=0 ANDROS_SIM_SCRIPTS=$seeds \
    "$build_dir/tests/andros_simulation_tests" --gtest_filter='FaultSimulation.RandomScriptsWithFaultsKeepTheSafetyRules' |
    sed -n 's/^fault simulation: \([0-9]*\) of [0-9]* seeds broke a rule.*/\1/p'
}

status=0
baseline=$(run_simulation)
printf '%-56s %s\n' "mutation" "seeds that caught it (of $seeds)"
printf '%-56s %s\n' "(none: the code as it is)" "$baseline"
[[ $baseline == 0 ]] || status=1
n=0
for m in "${mutations[@]}"; do
  n=$((n + 1))
  IFS='|' read -r name file expr <<<"$m"
  if [[ -n ${MUTATIONS:-} && " $MUTATIONS " != *" $n "* ]]; then continue; fi
  saved="$backup/$(tr '/' '%' <<<"$file")"
  cp "$file" "$saved"
  perl -0pi -e "$expr" "$file"
  if cmp -s "$file" "$saved"; then
    printf '%2d %-53s %s\n' "$n" "$name" "NOT APPLIED: its text is no longer in $file"
    status=1
    continue
  fi
  caught=$(run_simulation || true)
  cp "$saved" "$file"
  rm "$saved"
  printf '%2d %-53s %s\n' "$n" "$name" "${caught:-the build failed}"
  [[ ${caught:-0} -gt 0 ]] || status=1
done
cmake --build "$build_dir" --target andros_simulation_tests >/dev/null  # the code as it is, again
exit $status
