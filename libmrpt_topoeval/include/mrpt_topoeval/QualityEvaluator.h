/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// Deprecated name (no class QualityEvaluator exists), kept so that existing code compiles: include
// <mrpt_topoeval/evaluation/evaluate_match.h> (evaluateMatch(), QualityParameters) and
// <mrpt_topoeval/pipeline/evaluate.h> (evaluate()), or <mrpt_topoeval/topoeval.h>.
#include <mrpt_topoeval/evaluation/evaluate_match.h>
#include <mrpt_topoeval/pipeline/evaluate.h>
