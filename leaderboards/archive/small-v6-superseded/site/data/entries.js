window.SYMBENCH_ENTRIES = {
 "hexa-climb-small-v6__converge__fraction-0.1__ffnn-leg__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--fraction-0-1",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__fraction-0.1__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3-4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.364 [0.329, 0.390]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.449 [0.405, 0.482]",
    "lower"
   ],
   [
    "equiv_err",
    "1.25 [1.10, 1.39]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "172 306",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "9 500 [9 000, 10 000]",
    ""
   ],
   [
    "epochs",
    "202 [191, 212]",
    ""
   ],
   [
    "stopped_by",
    "patience 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.1",
  "title": "ffnn-leg (acc, torch)"
 },
 "hexa-climb-small-v6__converge__fraction-0.1__ffnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--fraction-0-1",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__fraction-0.1__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4-5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.610 [0.559, 0.659]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.752 [0.689, 0.814]",
    "lower"
   ],
   [
    "equiv_err",
    "1.30 [1.13, 1.40]",
    "lower"
   ],
   [
    "invar_change",
    "1.37 [1.28, 1.53]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "157 970",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "9 167 [7 500, 10 000]",
    ""
   ],
   [
    "epochs",
    "194 [159, 212]",
    ""
   ],
   [
    "stopped_by",
    "budget 1, patience 2",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.1",
  "title": "ffnn (acc, torch)"
 },
 "hexa-climb-small-v6__converge__fraction-0.1__gnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--fraction-0-1",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__fraction-0.1__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1-5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.466 [0.388, 0.620]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.574 [0.479, 0.764]",
    "lower"
   ],
   [
    "equiv_err",
    "1.40 [1.10, 1.89]",
    "lower"
   ],
   [
    "invar_change",
    "1.61 [1.52, 1.71]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "8 333 [6 000, 10 000]",
    ""
   ],
   [
    "epochs",
    "177 [127, 212]",
    ""
   ],
   [
    "stopped_by",
    "budget 1, patience 2",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.1",
  "title": "gnn (acc, torch)"
 },
 "hexa-climb-small-v6__converge__fraction-0.1__sdgnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--fraction-0-1",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__fraction-0.1__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1-3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.121 [0.085, 0.150]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.150 [0.105, 0.185]",
    "lower"
   ],
   [
    "equiv_err",
    "4.09 × 10⁻⁷ [3.87 × 10⁻⁷, 4.21 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "212",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.1",
  "title": "sdgnn (acc, torch)"
 },
 "hexa-climb-small-v6__converge__fraction-0.1__sdnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--fraction-0-1",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__fraction-0.1__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1-3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0996 [0.0618, 0.1260]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.123 [0.076, 0.156]",
    "lower"
   ],
   [
    "equiv_err",
    "3.09 × 10⁻⁷ [3.07 × 10⁻⁷, 3.12 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "212",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.1",
  "title": "sdnn (acc, torch)"
 },
 "hexa-climb-small-v6__converge__fraction-0.25__ffnn-leg__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--fraction-0-25",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__fraction-0.25__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.210 [0.197, 0.223]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.259 [0.242, 0.276]",
    "lower"
   ],
   [
    "equiv_err",
    "1.06 [1.03, 1.08]",
    "lower"
   ],
   [
    "invar_change",
    "3.49 × 10⁻⁸ [0.00 × 10⁻⁸, 10.46 × 10⁻⁸]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "172 306",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "9 167 [9 000, 9 500]",
    ""
   ],
   [
    "epochs",
    "79.3 [78.0, 82.0]",
    ""
   ],
   [
    "stopped_by",
    "patience 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.25",
  "title": "ffnn-leg (acc, torch)"
 },
 "hexa-climb-small-v6__converge__fraction-0.25__ffnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--fraction-0-25",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__fraction-0.25__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.396 [0.369, 0.444]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.489 [0.455, 0.548]",
    "lower"
   ],
   [
    "equiv_err",
    "1.17 [1.01, 1.26]",
    "lower"
   ],
   [
    "invar_change",
    "1.48 [1.35, 1.70]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "157 970",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "7 500 [5 500, 9 500]",
    ""
   ],
   [
    "epochs",
    "64.7 [47.0, 82.0]",
    ""
   ],
   [
    "stopped_by",
    "patience 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.25",
  "title": "ffnn (acc, torch)"
 },
 "hexa-climb-small-v6__converge__fraction-0.25__gnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--fraction-0-25",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__fraction-0.25__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0987 [0.0827, 0.1189]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.122 [0.102, 0.147]",
    "lower"
   ],
   [
    "equiv_err",
    "1.40 [1.22, 1.54]",
    "lower"
   ],
   [
    "invar_change",
    "1.61 [1.55, 1.64]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "9 833 [9 500, 10 000]",
    ""
   ],
   [
    "epochs",
    "84.7 [82.0, 86.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 1, patience 2",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.25",
  "title": "gnn (acc, torch)"
 },
 "hexa-climb-small-v6__converge__fraction-0.25__sdgnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--fraction-0-25",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__fraction-0.25__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0379 [0.0241, 0.0626]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0467 [0.0297, 0.0772]",
    "lower"
   ],
   [
    "equiv_err",
    "3.68 × 10⁻⁷ [3.33 × 10⁻⁷, 4.10 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "3.42 × 10⁻⁸ [0.00 × 10⁻⁸, 10.26 × 10⁻⁸]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "86.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.25",
  "title": "sdgnn (acc, torch)"
 },
 "hexa-climb-small-v6__converge__fraction-0.25__sdnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--fraction-0-25",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__fraction-0.25__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0273 [0.0165, 0.0475]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0337 [0.0204, 0.0586]",
    "lower"
   ],
   [
    "equiv_err",
    "3.10 × 10⁻⁷ [3.09 × 10⁻⁷, 3.11 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "3.43 × 10⁻⁸ [0.00 × 10⁻⁸, 10.29 × 10⁻⁸]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "9 500 [8 500, 10 000]",
    ""
   ],
   [
    "epochs",
    "81.7 [73.0, 86.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 1",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.25",
  "title": "sdnn (acc, torch)"
 },
 "hexa-climb-small-v6__converge__fraction-0.5__ffnn-leg__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--fraction-0-5",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__fraction-0.5__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.144 [0.136, 0.152]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.177 [0.168, 0.187]",
    "lower"
   ],
   [
    "equiv_err",
    "0.867 [0.775, 0.990]",
    "lower"
   ],
   [
    "invar_change",
    "6.91 × 10⁻⁸ [0.00 × 10⁻⁸, 20.72 × 10⁻⁸]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "172 306",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "44.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.5",
  "title": "ffnn-leg (acc, torch)"
 },
 "hexa-climb-small-v6__converge__fraction-0.5__ffnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--fraction-0-5",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__fraction-0.5__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.259 [0.247, 0.266]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.319 [0.304, 0.328]",
    "lower"
   ],
   [
    "equiv_err",
    "1.24 [1.22, 1.27]",
    "lower"
   ],
   [
    "invar_change",
    "1.49 [1.42, 1.62]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "157 970",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "6 833 [5 500, 7 500]",
    ""
   ],
   [
    "epochs",
    "30.0 [24.0, 33.0]",
    ""
   ],
   [
    "stopped_by",
    "patience 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.5",
  "title": "ffnn (acc, torch)"
 },
 "hexa-climb-small-v6__converge__fraction-0.5__gnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--fraction-0-5",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__fraction-0.5__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2-3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0342 [0.0285, 0.0420]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0422 [0.0352, 0.0519]",
    "lower"
   ],
   [
    "equiv_err",
    "0.695 [0.130, 1.543]",
    "lower"
   ],
   [
    "invar_change",
    "1.64 [1.51, 1.72]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "44.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.5",
  "title": "gnn (acc, torch)"
 },
 "hexa-climb-small-v6__converge__fraction-0.5__sdgnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--fraction-0-5",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__fraction-0.5__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2-3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0243 [0.0221, 0.0258]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0300 [0.0273, 0.0318]",
    "lower"
   ],
   [
    "equiv_err",
    "3.57 × 10⁻⁷ [3.10 × 10⁻⁷, 4.06 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "5.07 × 10⁻⁸ [0.00 × 10⁻⁸, 15.22 × 10⁻⁸]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "44.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.5",
  "title": "sdgnn (acc, torch)"
 },
 "hexa-climb-small-v6__converge__fraction-0.5__sdnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--fraction-0-5",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__fraction-0.5__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0126 [0.0111, 0.0152]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0155 [0.0137, 0.0187]",
    "lower"
   ],
   [
    "equiv_err",
    "3.06 × 10⁻⁷ [3.05 × 10⁻⁷, 3.08 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "4.28 × 10⁻⁸ [0.00 × 10⁻⁸, 12.83 × 10⁻⁸]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "44.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.5",
  "title": "sdnn (acc, torch)"
 },
 "hexa-climb-small-v6__converge__fraction-0.75__ffnn-leg__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--fraction-0-75",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__fraction-0.75__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.114 [0.101, 0.132]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.141 [0.125, 0.162]",
    "lower"
   ],
   [
    "equiv_err",
    "0.654 [0.600, 0.708]",
    "lower"
   ],
   [
    "invar_change",
    "1.57 × 10⁻⁸ [0.00 × 10⁻⁸, 4.70 × 10⁻⁸]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "172 306",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "30.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.75",
  "title": "ffnn-leg (acc, torch)"
 },
 "hexa-climb-small-v6__converge__fraction-0.75__ffnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--fraction-0-75",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__fraction-0.75__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.193 [0.186, 0.201]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.238 [0.230, 0.247]",
    "lower"
   ],
   [
    "equiv_err",
    "1.21 [1.14, 1.28]",
    "lower"
   ],
   [
    "invar_change",
    "1.52 [1.50, 1.54]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "157 970",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "9 667 [9 500, 10 000]",
    ""
   ],
   [
    "epochs",
    "28.7 [28.0, 30.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 1, patience 2",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.75",
  "title": "ffnn (acc, torch)"
 },
 "hexa-climb-small-v6__converge__fraction-0.75__gnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--fraction-0-75",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__fraction-0.75__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2-3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0274 [0.0244, 0.0321]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0338 [0.0301, 0.0396]",
    "lower"
   ],
   [
    "equiv_err",
    "0.462 [0.404, 0.510]",
    "lower"
   ],
   [
    "invar_change",
    "1.62 [1.59, 1.67]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "30.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.75",
  "title": "gnn (acc, torch)"
 },
 "hexa-climb-small-v6__converge__fraction-0.75__sdgnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--fraction-0-75",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__fraction-0.75__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2-3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0244 [0.0232, 0.0254]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0301 [0.0287, 0.0313]",
    "lower"
   ],
   [
    "equiv_err",
    "4.10 × 10⁻⁷ [4.04 × 10⁻⁷, 4.14 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "1.11 × 10⁻⁷ [0.00 × 10⁻⁷, 3.34 × 10⁻⁷]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "30.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.75",
  "title": "sdgnn (acc, torch)"
 },
 "hexa-climb-small-v6__converge__fraction-0.75__sdnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--fraction-0-75",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__fraction-0.75__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0138 [0.0128, 0.0156]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0170 [0.0159, 0.0193]",
    "lower"
   ],
   [
    "equiv_err",
    "3.07 × 10⁻⁷ [3.07 × 10⁻⁷, 3.08 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "3.41 × 10⁻⁸ [0.00 × 10⁻⁸, 10.23 × 10⁻⁸]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "30.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.75",
  "title": "sdnn (acc, torch)"
 },
 "hexa-climb-small-v6__converge__iid__ffnn-leg__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--iid",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__iid__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0900 [0.0824, 0.0982]",
    "lower"
   ],
   [
    "cl_score",
    "0.430 [0.405, 0.445]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.111 [0.102, 0.121]",
    "lower"
   ],
   [
    "equiv_err",
    "0.626 [0.561, 0.700]",
    "lower"
   ],
   [
    "invar_change",
    "1.69 × 10⁻⁸ [0.00 × 10⁻⁸, 5.07 × 10⁻⁸]",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "1.24 [1.18, 1.27]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0367 [0.0322, 0.0418]",
    "lower"
   ],
   [
    "parameters",
    "172 306",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "22.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "iid",
  "title": "ffnn-leg (acc, torch)"
 },
 "hexa-climb-small-v6__converge__iid__ffnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--iid",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__iid__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.141 [0.128, 0.156]",
    "lower"
   ],
   [
    "cl_score",
    "0.429 [0.418, 0.444]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.174 [0.158, 0.192]",
    "lower"
   ],
   [
    "equiv_err",
    "1.35 [1.26, 1.50]",
    "lower"
   ],
   [
    "invar_change",
    "1.56 [1.54, 1.58]",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "1.24 [1.21, 1.27]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0520 [0.0457, 0.0625]",
    "lower"
   ],
   [
    "parameters",
    "157 970",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "22.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "iid",
  "title": "ffnn (acc, torch)"
 },
 "hexa-climb-small-v6__converge__iid__gnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--iid",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__iid__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2-3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0263 [0.0231, 0.0281]",
    "lower"
   ],
   [
    "cl_score",
    "0.299 [0.215, 0.417]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0324 [0.0285, 0.0347]",
    "lower"
   ],
   [
    "equiv_err",
    "0.290 [0.107, 0.401]",
    "lower"
   ],
   [
    "invar_change",
    "1.66 [1.53, 1.75]",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.926 [0.726, 1.206]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0654 [0.0576, 0.0698]",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "22.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "iid",
  "title": "gnn (acc, torch)"
 },
 "hexa-climb-small-v6__converge__iid__sdgnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--iid",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__iid__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1-2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0230 [0.0202, 0.0247]",
    "lower"
   ],
   [
    "cl_score",
    "0.885 [0.859, 0.900]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0283 [0.0249, 0.0305]",
    "lower"
   ],
   [
    "equiv_err",
    "3.58 × 10⁻⁷ [3.05 × 10⁻⁷, 4.06 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "6.94 × 10⁻⁸ [0.00 × 10⁻⁸, 20.82 × 10⁻⁸]",
    "lower"
   ],
   [
    "cl_success",
    "0.667",
    "higher"
   ],
   [
    "cl_held_s",
    "2.33 [2.26, 2.36]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0236 [0.0184, 0.0334]",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "22.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "iid",
  "title": "sdgnn (acc, torch)"
 },
 "hexa-climb-small-v6__converge__iid__sdnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--iid",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__iid__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1-3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0150 [0.0133, 0.0170]",
    "lower"
   ],
   [
    "cl_score",
    "0.973 [0.941, 1.000]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0185 [0.0164, 0.0210]",
    "lower"
   ],
   [
    "equiv_err",
    "3.07 × 10⁻⁷ [3.06 × 10⁻⁷, 3.07 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "3.41 × 10⁻⁸ [0.00 × 10⁻⁸, 10.22 × 10⁻⁸]",
    "lower"
   ],
   [
    "cl_success",
    "0.889 [0.833, 1.000]",
    "higher"
   ],
   [
    "cl_held_s",
    "2.54 [2.46, 2.60]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0233 [0.0181, 0.0323]",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "9 667 [9 000, 10 000]",
    ""
   ],
   [
    "epochs",
    "21.3 [20.0, 22.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 1",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "iid",
  "title": "sdnn (acc, torch)"
 },
 "hexa-climb-small-v6__converge__orbit-rotation__ffnn-leg__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--orbit-rotation",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__orbit-rotation__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.904 [0.894, 0.918]",
    "lower"
   ],
   [
    "cl_score",
    "0.118 [0.113, 0.121]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "1.12 [1.10, 1.13]",
    "lower"
   ],
   [
    "equiv_err",
    "2.05 [2.03, 2.07]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.493 [0.483, 0.502]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.104 [0.099, 0.107]",
    "lower"
   ],
   [
    "parameters",
    "172 306",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "106",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 1",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "orbit-rotation",
  "title": "ffnn-leg (acc, torch)"
 },
 "hexa-climb-small-v6__converge__orbit-rotation__ffnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--orbit-rotation",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__orbit-rotation__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "1.01 [1.00, 1.02]",
    "lower"
   ],
   [
    "cl_score",
    "0.105 [0.095, 0.118]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "1.25 [1.24, 1.26]",
    "lower"
   ],
   [
    "equiv_err",
    "1.63 [1.59, 1.68]",
    "lower"
   ],
   [
    "invar_change",
    "1.13 [1.13, 1.14]",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.463 [0.438, 0.493]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0946 [0.0880, 0.0991]",
    "lower"
   ],
   [
    "parameters",
    "157 970",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "9 500 [8 500, 10 000]",
    ""
   ],
   [
    "epochs",
    "101 [90, 106]",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 1",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "orbit-rotation",
  "title": "ffnn (acc, torch)"
 },
 "hexa-climb-small-v6__converge__orbit-rotation__gnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--orbit-rotation",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__orbit-rotation__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.543 [0.496, 0.576]",
    "lower"
   ],
   [
    "cl_score",
    "0.184 [0.148, 0.220]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.671 [0.612, 0.711]",
    "lower"
   ],
   [
    "equiv_err",
    "1.39 [1.28, 1.51]",
    "lower"
   ],
   [
    "invar_change",
    "1.51 [1.45, 1.54]",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.652 [0.566, 0.737]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0795 [0.0727, 0.0838]",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "106",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "orbit-rotation",
  "title": "gnn (acc, torch)"
 },
 "hexa-climb-small-v6__converge__orbit-rotation__sdgnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--orbit-rotation",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__orbit-rotation__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0238 [0.0227, 0.0254]",
    "lower"
   ],
   [
    "cl_score",
    "0.679 [0.490, 0.790]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0293 [0.0280, 0.0314]",
    "lower"
   ],
   [
    "equiv_err",
    "3.56 × 10⁻⁷ [3.08 × 10⁻⁷, 4.02 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.278 [0.000, 0.500]",
    "higher"
   ],
   [
    "cl_held_s",
    "1.83 [1.38, 2.10]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0303 [0.0263, 0.0337]",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "106",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "orbit-rotation",
  "title": "sdgnn (acc, torch)"
 },
 "hexa-climb-small-v6__converge__orbit-rotation__sdnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--orbit-rotation",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__orbit-rotation__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0131 [0.0115, 0.0162]",
    "lower"
   ],
   [
    "cl_score",
    "0.773 [0.636, 0.903]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0162 [0.0142, 0.0200]",
    "lower"
   ],
   [
    "equiv_err",
    "3.58 × 10⁻⁷ [3.03 × 10⁻⁷, 4.12 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.500 [0.333, 0.667]",
    "higher"
   ],
   [
    "cl_held_s",
    "2.06 [1.73, 2.37]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0270 [0.0248, 0.0304]",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "9 500 [8 500, 10 000]",
    ""
   ],
   [
    "epochs",
    "101 [90, 106]",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 1",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "orbit-rotation",
  "title": "sdnn (acc, torch)"
 },
 "hexa-climb-small-v6__converge__unseen-heading__ffnn-leg__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--unseen-heading",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__unseen-heading__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0636 [0.0571, 0.0733]",
    "lower"
   ],
   [
    "cl_score",
    "0.551 [0.361, 0.788]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0784 [0.0705, 0.0905]",
    "lower"
   ],
   [
    "equiv_err",
    "0.600 [0.531, 0.710]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.222 [0.000, 0.500]",
    "higher"
   ],
   [
    "cl_held_s",
    "1.53 [1.07, 2.09]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0334 [0.0304, 0.0378]",
    "lower"
   ],
   [
    "parameters",
    "172 306",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "36.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "unseen-heading",
  "title": "ffnn-leg (acc, torch)"
 },
 "hexa-climb-small-v6__converge__unseen-heading__ffnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--unseen-heading",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__unseen-heading__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "1.03 [0.99, 1.05]",
    "lower"
   ],
   [
    "cl_score",
    "0.0254 [0.0014, 0.0456]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "1.27 [1.22, 1.30]",
    "lower"
   ],
   [
    "equiv_err",
    "0.871 [0.581, 1.195]",
    "lower"
   ],
   [
    "invar_change",
    "0.866 [0.043, 1.300]",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.272 [0.215, 0.320]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0967 [0.0914, 0.1006]",
    "lower"
   ],
   [
    "parameters",
    "157 970",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "9 333 [8 000, 10 000]",
    ""
   ],
   [
    "epochs",
    "33.3 [28.0, 36.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 1",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "unseen-heading",
  "title": "ffnn (acc, torch)"
 },
 "hexa-climb-small-v6__converge__unseen-heading__gnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--unseen-heading",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__unseen-heading__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.721 [0.693, 0.763]",
    "lower"
   ],
   [
    "cl_score",
    "0.0519 [0.0456, 0.0562]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.889 [0.855, 0.941]",
    "lower"
   ],
   [
    "equiv_err",
    "0.0276 [0.0261, 0.0291]",
    "lower"
   ],
   [
    "invar_change",
    "1.02 [0.18, 1.58]",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.335 [0.321, 0.346]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0874 [0.0834, 0.0909]",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "36.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "unseen-heading",
  "title": "gnn (acc, torch)"
 },
 "hexa-climb-small-v6__converge__unseen-heading__sdgnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--unseen-heading",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__unseen-heading__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0257 [0.0230, 0.0283]",
    "lower"
   ],
   [
    "cl_score",
    "0.726 [0.695, 0.745]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0317 [0.0284, 0.0349]",
    "lower"
   ],
   [
    "equiv_err",
    "3.41 × 10⁻⁷ [3.01 × 10⁻⁷, 3.63 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.389 [0.333, 0.500]",
    "higher"
   ],
   [
    "cl_held_s",
    "1.95 [1.87, 1.99]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0209 [0.0192, 0.0228]",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "36.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "unseen-heading",
  "title": "sdgnn (acc, torch)"
 },
 "hexa-climb-small-v6__converge__unseen-heading__sdnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--unseen-heading",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__unseen-heading__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0132 [0.0115, 0.0154]",
    "lower"
   ],
   [
    "cl_score",
    "0.802 [0.746, 0.905]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0163 [0.0142, 0.0190]",
    "lower"
   ],
   [
    "equiv_err",
    "3.07 × 10⁻⁷ [3.04 × 10⁻⁷, 3.09 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.556 [0.333, 0.833]",
    "higher"
   ],
   [
    "cl_held_s",
    "2.13 [1.99, 2.37]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0306 [0.0269, 0.0362]",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "36.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "unseen-heading",
  "title": "sdnn (acc, torch)"
 },
 "hexa-climb-small-v6__converge__unseen-rotation__ffnn-leg__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--unseen-rotation",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__unseen-rotation__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "1.00 [1.00, 1.01]",
    "lower"
   ],
   [
    "cl_score",
    "0.0671 [0.0615, 0.0712]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "1.23 [1.22, 1.23]",
    "lower"
   ],
   [
    "equiv_err",
    "1.78 [1.77, 1.80]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.374 [0.360, 0.384]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.104 [0.099, 0.113]",
    "lower"
   ],
   [
    "parameters",
    "172 306",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "212",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "unseen-rotation",
  "title": "ffnn-leg (acc, torch)"
 },
 "hexa-climb-small-v6__converge__unseen-rotation__ffnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--unseen-rotation",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__unseen-rotation__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "1.04 [1.04, 1.05]",
    "lower"
   ],
   [
    "cl_score",
    "0.0611 [0.0557, 0.0672]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "1.28 [1.27, 1.28]",
    "lower"
   ],
   [
    "equiv_err",
    "1.62 [1.60, 1.67]",
    "lower"
   ],
   [
    "invar_change",
    "1.07 [0.89, 1.23]",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.359 [0.347, 0.374]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.100 [0.097, 0.103]",
    "lower"
   ],
   [
    "parameters",
    "157 970",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "212",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "unseen-rotation",
  "title": "ffnn (acc, torch)"
 },
 "hexa-climb-small-v6__converge__unseen-rotation__gnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--unseen-rotation",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__unseen-rotation__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.523 [0.494, 0.551]",
    "lower"
   ],
   [
    "cl_score",
    "0.301 [0.220, 0.370]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.640 [0.604, 0.675]",
    "lower"
   ],
   [
    "equiv_err",
    "1.29 [1.22, 1.43]",
    "lower"
   ],
   [
    "invar_change",
    "1.47 [1.41, 1.51]",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.931 [0.738, 1.097]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0785 [0.0753, 0.0845]",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "212",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "unseen-rotation",
  "title": "gnn (acc, torch)"
 },
 "hexa-climb-small-v6__converge__unseen-rotation__sdgnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--unseen-rotation",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__unseen-rotation__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.172 [0.169, 0.177]",
    "lower"
   ],
   [
    "cl_score",
    "0.663 [0.588, 0.724]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.211 [0.207, 0.216]",
    "lower"
   ],
   [
    "equiv_err",
    "4.11 × 10⁻⁷ [3.93 × 10⁻⁷, 4.44 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.333",
    "higher"
   ],
   [
    "cl_held_s",
    "1.80 [1.62, 1.94]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0339 [0.0336, 0.0343]",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "212",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "unseen-rotation",
  "title": "sdgnn (acc, torch)"
 },
 "hexa-climb-small-v6__converge__unseen-rotation__sdnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#converge--unseen-rotation",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__converge__unseen-rotation__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.144 [0.135, 0.157]",
    "lower"
   ],
   [
    "cl_score",
    "0.485 [0.464, 0.509]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.176 [0.165, 0.193]",
    "lower"
   ],
   [
    "equiv_err",
    "3.26 × 10⁻⁷ [3.03 × 10⁻⁷, 3.66 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "1.37 [1.32, 1.43]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0411 [0.0355, 0.0496]",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "8 333 [5 000, 10 000]",
    ""
   ],
   [
    "epochs",
    "177 [106, 212]",
    ""
   ],
   [
    "stopped_by",
    "budget 1, patience 2",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "unseen-rotation",
  "title": "sdnn (acc, torch)"
 },
 "hexa-climb-small-v6__cosine__fraction-0.1__ffnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#cosine--fraction-0-1",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__cosine__fraction-0.1__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.615 [0.571, 0.658]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.759 [0.704, 0.813]",
    "lower"
   ],
   [
    "equiv_err",
    "1.27 [1.10, 1.37]",
    "lower"
   ],
   [
    "invar_change",
    "1.46 [1.30, 1.55]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "157 970",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "8 667 [8 500, 9 000]",
    ""
   ],
   [
    "epochs",
    "184 [180, 191]",
    ""
   ],
   [
    "stopped_by",
    "patience 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "cosine",
  "robot": "hexa",
  "split": "fraction-0.1",
  "title": "ffnn (acc, torch)"
 },
 "hexa-climb-small-v6__cosine__fraction-0.1__sdnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#cosine--fraction-0-1",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__cosine__fraction-0.1__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.103 [0.066, 0.125]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.127 [0.082, 0.154]",
    "lower"
   ],
   [
    "equiv_err",
    "3.77 × 10⁻⁷ [3.62 × 10⁻⁷, 4.05 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "8 833 [8 000, 10 000]",
    ""
   ],
   [
    "epochs",
    "187 [170, 212]",
    ""
   ],
   [
    "stopped_by",
    "budget 1, patience 2",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "cosine",
  "robot": "hexa",
  "split": "fraction-0.1",
  "title": "sdnn (acc, torch)"
 },
 "hexa-climb-small-v6__cosine__iid__ffnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#cosine--iid",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__cosine__iid__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.133 [0.122, 0.149]",
    "lower"
   ],
   [
    "cl_score",
    "0.441 [0.352, 0.528]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.164 [0.150, 0.184]",
    "lower"
   ],
   [
    "equiv_err",
    "1.48 [1.25, 1.80]",
    "lower"
   ],
   [
    "invar_change",
    "1.69 [1.56, 1.90]",
    "lower"
   ],
   [
    "cl_success",
    "0.0556 [0.0000, 0.1667]",
    "higher"
   ],
   [
    "cl_held_s",
    "1.27 [1.05, 1.47]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0461 [0.0408, 0.0548]",
    "lower"
   ],
   [
    "parameters",
    "157 970",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "22.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "cosine",
  "robot": "hexa",
  "split": "iid",
  "title": "ffnn (acc, torch)"
 },
 "hexa-climb-small-v6__cosine__iid__sdnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#cosine--iid",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__cosine__iid__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.00524 [0.00505, 0.00544]",
    "lower"
   ],
   [
    "cl_score",
    "0.966 [0.949, 1.000]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.00646 [0.00622, 0.00671]",
    "lower"
   ],
   [
    "equiv_err",
    "3.90 × 10⁻⁷ [3.58 × 10⁻⁷, 4.06 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "3.38 × 10⁻⁸ [0.00 × 10⁻⁸, 10.15 × 10⁻⁸]",
    "lower"
   ],
   [
    "cl_success",
    "0.889 [0.833, 1.000]",
    "higher"
   ],
   [
    "cl_held_s",
    "2.52 [2.48, 2.60]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0191 [0.0181, 0.0198]",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "22.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "cosine",
  "robot": "hexa",
  "split": "iid",
  "title": "sdnn (acc, torch)"
 },
 "hexa-climb-small-v6__cosine__unseen-rotation__ffnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#cosine--unseen-rotation",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__cosine__unseen-rotation__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "1.04 [1.03, 1.05]",
    "lower"
   ],
   [
    "cl_score",
    "0.0626 [0.0554, 0.0683]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "1.28 [1.26, 1.28]",
    "lower"
   ],
   [
    "equiv_err",
    "1.63 [1.57, 1.66]",
    "lower"
   ],
   [
    "invar_change",
    "1.17 [1.04, 1.42]",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.363 [0.346, 0.377]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.100 [0.098, 0.102]",
    "lower"
   ],
   [
    "parameters",
    "157 970",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "212",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "cosine",
  "robot": "hexa",
  "split": "unseen-rotation",
  "title": "ffnn (acc, torch)"
 },
 "hexa-climb-small-v6__cosine__unseen-rotation__sdnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v6.html#cosine--unseen-rotation",
  "dataset": "hexa-climb-small-v6",
  "entry": "entries/hexa-climb-small-v6__cosine__unseen-rotation__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.147 [0.144, 0.151]",
    "lower"
   ],
   [
    "cl_score",
    "0.558 [0.474, 0.695]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.179 [0.176, 0.184]",
    "lower"
   ],
   [
    "equiv_err",
    "3.38 × 10⁻⁷ [2.97 × 10⁻⁷, 4.07 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.167 [0.000, 0.333]",
    "higher"
   ],
   [
    "cl_held_s",
    "1.55 [1.34, 1.87]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0399 [0.0324, 0.0509]",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "212",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "cosine",
  "robot": "hexa",
  "split": "unseen-rotation",
  "title": "sdnn (acc, torch)"
 },
 "magneto-climb-small-v6__converge__fraction-0.1__ffnn-leg__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--fraction-0-1",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__fraction-0.1__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2-3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.454 [0.438, 0.463]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.354 [0.341, 0.361]",
    "lower"
   ],
   [
    "equiv_err",
    "0.775 [0.717, 0.868]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "158 988",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "9 167 [7 500, 10 000]",
    ""
   ],
   [
    "epochs",
    "194 [159, 212]",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 1",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.1",
  "title": "ffnn-leg (acc, torch)"
 },
 "magneto-climb-small-v6__converge__fraction-0.1__ffnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--fraction-0-1",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__fraction-0.1__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4-5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.782 [0.760, 0.797]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.610 [0.592, 0.620]",
    "lower"
   ],
   [
    "equiv_err",
    "1.23 [1.04, 1.47]",
    "lower"
   ],
   [
    "invar_change",
    "1.30 [1.17, 1.44]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "150 796",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "7 333 [4 500, 10 000]",
    ""
   ],
   [
    "epochs",
    "155 [95, 212]",
    ""
   ],
   [
    "stopped_by",
    "budget 1, patience 2",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.1",
  "title": "ffnn (acc, torch)"
 },
 "magneto-climb-small-v6__converge__fraction-0.1__gnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--fraction-0-1",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__fraction-0.1__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4-5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.892 [0.807, 0.949]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.695 [0.628, 0.739]",
    "lower"
   ],
   [
    "equiv_err",
    "1.37 [1.26, 1.48]",
    "lower"
   ],
   [
    "invar_change",
    "1.57 [1.47, 1.73]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "7 000 [5 500, 10 000]",
    ""
   ],
   [
    "epochs",
    "149 [117, 212]",
    ""
   ],
   [
    "stopped_by",
    "budget 1, patience 2",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.1",
  "title": "gnn (acc, torch)"
 },
 "magneto-climb-small-v6__converge__fraction-0.1__sdgnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--fraction-0-1",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__fraction-0.1__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2-3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.443 [0.434, 0.454]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.345 [0.339, 0.354]",
    "lower"
   ],
   [
    "equiv_err",
    "3.63 × 10⁻⁷ [3.06 × 10⁻⁷, 4.29 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "212",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.1",
  "title": "sdgnn (acc, torch)"
 },
 "magneto-climb-small-v6__converge__fraction-0.1__sdnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--fraction-0-1",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__fraction-0.1__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.263 [0.245, 0.280]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.205 [0.191, 0.219]",
    "lower"
   ],
   [
    "equiv_err",
    "2.86 × 10⁻⁷ [2.53 × 10⁻⁷, 3.49 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "212",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.1",
  "title": "sdnn (acc, torch)"
 },
 "magneto-climb-small-v6__converge__fraction-0.25__ffnn-leg__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--fraction-0-25",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__fraction-0.25__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2-3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.202 [0.177, 0.231]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.157 [0.138, 0.180]",
    "lower"
   ],
   [
    "equiv_err",
    "0.526 [0.397, 0.686]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "158 988",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "9 667 [9 000, 10 000]",
    ""
   ],
   [
    "epochs",
    "83.3 [78.0, 86.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 1",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.25",
  "title": "ffnn-leg (acc, torch)"
 },
 "magneto-climb-small-v6__converge__fraction-0.25__ffnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--fraction-0-25",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__fraction-0.25__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4-5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.428 [0.381, 0.493]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.333 [0.297, 0.385]",
    "lower"
   ],
   [
    "equiv_err",
    "1.07 [0.98, 1.20]",
    "lower"
   ],
   [
    "invar_change",
    "1.28 [1.24, 1.32]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "150 796",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "7 833 [3 500, 10 000]",
    ""
   ],
   [
    "epochs",
    "67.3 [30.0, 86.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 1",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.25",
  "title": "ffnn (acc, torch)"
 },
 "magneto-climb-small-v6__converge__fraction-0.25__gnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--fraction-0-25",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__fraction-0.25__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4-5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.564 [0.434, 0.680]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.439 [0.338, 0.531]",
    "lower"
   ],
   [
    "equiv_err",
    "1.21 [1.02, 1.38]",
    "lower"
   ],
   [
    "invar_change",
    "1.56 [1.40, 1.64]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "8 833 [8 000, 10 000]",
    ""
   ],
   [
    "epochs",
    "76.0 [69.0, 86.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 1, patience 2",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.25",
  "title": "gnn (acc, torch)"
 },
 "magneto-climb-small-v6__converge__fraction-0.25__sdgnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--fraction-0-25",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__fraction-0.25__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2-3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.161 [0.130, 0.201]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.125 [0.102, 0.157]",
    "lower"
   ],
   [
    "equiv_err",
    "4.77 × 10⁻⁷ [3.26 × 10⁻⁷, 7.35 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "86.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.25",
  "title": "sdgnn (acc, torch)"
 },
 "magneto-climb-small-v6__converge__fraction-0.25__sdnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--fraction-0-25",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__fraction-0.25__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.106 [0.094, 0.130]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0826 [0.0732, 0.1011]",
    "lower"
   ],
   [
    "equiv_err",
    "2.73 × 10⁻⁷ [2.42 × 10⁻⁷, 3.18 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "86.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.25",
  "title": "sdnn (acc, torch)"
 },
 "magneto-climb-small-v6__converge__fraction-0.5__ffnn-leg__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--fraction-0-5",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__fraction-0.5__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2-3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.127 [0.109, 0.140]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0991 [0.0847, 0.1092]",
    "lower"
   ],
   [
    "equiv_err",
    "0.358 [0.298, 0.392]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "158 988",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "44.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.5",
  "title": "ffnn-leg (acc, torch)"
 },
 "magneto-climb-small-v6__converge__fraction-0.5__ffnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--fraction-0-5",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__fraction-0.5__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4-5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.272 [0.268, 0.275]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.212 [0.208, 0.215]",
    "lower"
   ],
   [
    "equiv_err",
    "1.15 [1.06, 1.27]",
    "lower"
   ],
   [
    "invar_change",
    "1.40 [1.33, 1.46]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "150 796",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "8 667 [6 000, 10 000]",
    ""
   ],
   [
    "epochs",
    "38.0 [26.0, 44.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 1",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.5",
  "title": "ffnn (acc, torch)"
 },
 "magneto-climb-small-v6__converge__fraction-0.5__gnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--fraction-0-5",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__fraction-0.5__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4-5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.213 [0.189, 0.245]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.166 [0.147, 0.191]",
    "lower"
   ],
   [
    "equiv_err",
    "1.13 [0.67, 1.52]",
    "lower"
   ],
   [
    "invar_change",
    "1.64 [1.57, 1.69]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "44.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.5",
  "title": "gnn (acc, torch)"
 },
 "magneto-climb-small-v6__converge__fraction-0.5__sdgnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--fraction-0-5",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__fraction-0.5__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2-3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.105 [0.084, 0.130]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0817 [0.0654, 0.1011]",
    "lower"
   ],
   [
    "equiv_err",
    "3.27 × 10⁻⁷ [2.76 × 10⁻⁷, 3.83 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "44.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.5",
  "title": "sdgnn (acc, torch)"
 },
 "magneto-climb-small-v6__converge__fraction-0.5__sdnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--fraction-0-5",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__fraction-0.5__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0717 [0.0559, 0.0895]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0559 [0.0435, 0.0697]",
    "lower"
   ],
   [
    "equiv_err",
    "3.07 × 10⁻⁷ [2.47 × 10⁻⁷, 3.76 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "44.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.5",
  "title": "sdnn (acc, torch)"
 },
 "magneto-climb-small-v6__converge__fraction-0.75__ffnn-leg__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--fraction-0-75",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__fraction-0.75__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2-3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0991 [0.0885, 0.1085]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0772 [0.0689, 0.0845]",
    "lower"
   ],
   [
    "equiv_err",
    "0.306 [0.269, 0.357]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "158 988",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "30.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.75",
  "title": "ffnn-leg (acc, torch)"
 },
 "magneto-climb-small-v6__converge__fraction-0.75__ffnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--fraction-0-75",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__fraction-0.75__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4-5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.173 [0.141, 0.194]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.135 [0.110, 0.151]",
    "lower"
   ],
   [
    "equiv_err",
    "1.19 [1.01, 1.35]",
    "lower"
   ],
   [
    "invar_change",
    "1.40 [1.35, 1.45]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "150 796",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "30.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.75",
  "title": "ffnn (acc, torch)"
 },
 "magneto-climb-small-v6__converge__fraction-0.75__gnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--fraction-0-75",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__fraction-0.75__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4-5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.144 [0.138, 0.157]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.113 [0.107, 0.122]",
    "lower"
   ],
   [
    "equiv_err",
    "0.851 [0.362, 1.219]",
    "lower"
   ],
   [
    "invar_change",
    "1.65 [1.53, 1.76]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "30.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.75",
  "title": "gnn (acc, torch)"
 },
 "magneto-climb-small-v6__converge__fraction-0.75__sdgnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--fraction-0-75",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__fraction-0.75__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2-3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0868 [0.0832, 0.0924]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0676 [0.0647, 0.0719]",
    "lower"
   ],
   [
    "equiv_err",
    "3.05 × 10⁻⁷ [2.99 × 10⁻⁷, 3.11 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "30.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.75",
  "title": "sdgnn (acc, torch)"
 },
 "magneto-climb-small-v6__converge__fraction-0.75__sdnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--fraction-0-75",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__fraction-0.75__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0617 [0.0570, 0.0703]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0481 [0.0444, 0.0547]",
    "lower"
   ],
   [
    "equiv_err",
    "2.43 × 10⁻⁷ [2.39 × 10⁻⁷, 2.49 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "30.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.75",
  "title": "sdnn (acc, torch)"
 },
 "magneto-climb-small-v6__converge__iid__ffnn-leg__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--iid",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__iid__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2-3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0866 [0.0800, 0.0984]",
    "lower"
   ],
   [
    "cl_score",
    "0.504 [0.389, 0.593]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0675 [0.0623, 0.0766]",
    "lower"
   ],
   [
    "equiv_err",
    "0.248 [0.201, 0.339]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "1.39 [1.11, 1.61]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0313 [0.0296, 0.0326]",
    "lower"
   ],
   [
    "parameters",
    "158 988",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "22.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "iid",
  "title": "ffnn-leg (acc, torch)"
 },
 "magneto-climb-small-v6__converge__iid__ffnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--iid",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__iid__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.136 [0.122, 0.150]",
    "lower"
   ],
   [
    "cl_score",
    "0.498 [0.448, 0.540]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.106 [0.095, 0.117]",
    "lower"
   ],
   [
    "equiv_err",
    "1.22 [0.89, 1.43]",
    "lower"
   ],
   [
    "invar_change",
    "1.40 [1.37, 1.44]",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "1.38 [1.26, 1.48]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0486 [0.0457, 0.0517]",
    "lower"
   ],
   [
    "parameters",
    "150 796",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "22.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "iid",
  "title": "ffnn (acc, torch)"
 },
 "magneto-climb-small-v6__converge__iid__gnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--iid",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__iid__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.110 [0.104, 0.121]",
    "lower"
   ],
   [
    "cl_score",
    "0.255 [0.164, 0.407]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0856 [0.0807, 0.0941]",
    "lower"
   ],
   [
    "equiv_err",
    "0.510 [0.194, 0.968]",
    "lower"
   ],
   [
    "invar_change",
    "1.65 [1.61, 1.68]",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.788 [0.565, 1.156]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0585 [0.0444, 0.0683]",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "22.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "iid",
  "title": "gnn (acc, torch)"
 },
 "magneto-climb-small-v6__converge__iid__sdgnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--iid",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__iid__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2-3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0774 [0.0756, 0.0795]",
    "lower"
   ],
   [
    "cl_score",
    "0.728 [0.690, 0.753]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0603 [0.0590, 0.0619]",
    "lower"
   ],
   [
    "equiv_err",
    "3.33 × 10⁻⁷ [3.14 × 10⁻⁷, 3.67 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.0556 [0.0000, 0.1667]",
    "higher"
   ],
   [
    "cl_held_s",
    "1.94 [1.84, 2.00]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0241 [0.0225, 0.0255]",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "22.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "iid",
  "title": "sdgnn (acc, torch)"
 },
 "magneto-climb-small-v6__converge__iid__sdnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--iid",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__iid__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0464 [0.0428, 0.0521]",
    "lower"
   ],
   [
    "cl_score",
    "0.722 [0.672, 0.823]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0361 [0.0334, 0.0406]",
    "lower"
   ],
   [
    "equiv_err",
    "3.03 × 10⁻⁷ [2.42 × 10⁻⁷, 3.68 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.222 [0.000, 0.333]",
    "higher"
   ],
   [
    "cl_held_s",
    "1.92 [1.80, 2.17]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0200 [0.0127, 0.0270]",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "22.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "iid",
  "title": "sdnn (acc, torch)"
 },
 "magneto-climb-small-v6__converge__orbit-rotation__ffnn-leg__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--orbit-rotation",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__orbit-rotation__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.828 [0.815, 0.835]",
    "lower"
   ],
   [
    "cl_score",
    "0.121 [0.109, 0.136]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.645 [0.635, 0.650]",
    "lower"
   ],
   [
    "equiv_err",
    "1.11 [1.06, 1.14]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.467 [0.437, 0.503]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0648 [0.0579, 0.0687]",
    "lower"
   ],
   [
    "parameters",
    "158 988",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "36.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "orbit-rotation",
  "title": "ffnn-leg (acc, torch)"
 },
 "magneto-climb-small-v6__converge__orbit-rotation__ffnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--orbit-rotation",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__orbit-rotation__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "1.02 [0.99, 1.05]",
    "lower"
   ],
   [
    "cl_score",
    "0.120 [0.087, 0.153]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.793 [0.771, 0.820]",
    "lower"
   ],
   [
    "equiv_err",
    "1.28 [1.25, 1.31]",
    "lower"
   ],
   [
    "invar_change",
    "1.37 [1.29, 1.50]",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.464 [0.385, 0.544]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0750 [0.0675, 0.0868]",
    "lower"
   ],
   [
    "parameters",
    "150 796",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "36.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "orbit-rotation",
  "title": "ffnn (acc, torch)"
 },
 "magneto-climb-small-v6__converge__orbit-rotation__gnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--orbit-rotation",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__orbit-rotation__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.558 [0.524, 0.602]",
    "lower"
   ],
   [
    "cl_score",
    "0.0737 [0.0689, 0.0797]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.434 [0.409, 0.469]",
    "lower"
   ],
   [
    "equiv_err",
    "1.17 [0.97, 1.32]",
    "lower"
   ],
   [
    "invar_change",
    "1.47 [1.37, 1.53]",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.352 [0.341, 0.367]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0846 [0.0780, 0.0895]",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "36.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "orbit-rotation",
  "title": "gnn (acc, torch)"
 },
 "magneto-climb-small-v6__converge__orbit-rotation__sdgnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--orbit-rotation",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__orbit-rotation__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0688 [0.0658, 0.0715]",
    "lower"
   ],
   [
    "cl_score",
    "0.607 [0.436, 0.798]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0536 [0.0512, 0.0557]",
    "lower"
   ],
   [
    "equiv_err",
    "3.15 × 10⁻⁷ [3.09 × 10⁻⁷, 3.19 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.0556 [0.0000, 0.1667]",
    "higher"
   ],
   [
    "cl_held_s",
    "1.65 [1.23, 2.11]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0249 [0.0205, 0.0296]",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "36.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "orbit-rotation",
  "title": "sdgnn (acc, torch)"
 },
 "magneto-climb-small-v6__converge__orbit-rotation__sdnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--orbit-rotation",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__orbit-rotation__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0427 [0.0414, 0.0445]",
    "lower"
   ],
   [
    "cl_score",
    "0.789 [0.721, 0.859]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0333 [0.0322, 0.0347]",
    "lower"
   ],
   [
    "equiv_err",
    "2.64 × 10⁻⁷ [2.43 × 10⁻⁷, 3.03 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.444 [0.333, 0.667]",
    "higher"
   ],
   [
    "cl_held_s",
    "2.09 [1.92, 2.26]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0278 [0.0239, 0.0323]",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "36.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "orbit-rotation",
  "title": "sdnn (acc, torch)"
 },
 "magneto-climb-small-v6__converge__unseen-heading__ffnn-leg__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--unseen-heading",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__unseen-heading__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2-3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0720 [0.0662, 0.0783]",
    "lower"
   ],
   [
    "cl_score",
    "0.532 [0.498, 0.569]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0561 [0.0515, 0.0610]",
    "lower"
   ],
   [
    "equiv_err",
    "0.274 [0.264, 0.291]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.111 [0.000, 0.333]",
    "higher"
   ],
   [
    "cl_held_s",
    "1.46 [1.38, 1.55]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0347 [0.0277, 0.0421]",
    "lower"
   ],
   [
    "parameters",
    "158 988",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "36.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "unseen-heading",
  "title": "ffnn-leg (acc, torch)"
 },
 "magneto-climb-small-v6__converge__unseen-heading__ffnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--unseen-heading",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__unseen-heading__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "1.63 [1.57, 1.67]",
    "lower"
   ],
   [
    "cl_score",
    "-0.00391 [-0.02005, 0.01071]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "1.27 [1.22, 1.30]",
    "lower"
   ],
   [
    "equiv_err",
    "0.632 [0.393, 0.755]",
    "lower"
   ],
   [
    "invar_change",
    "1.06 [0.06, 1.68]",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.164 [0.125, 0.199]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.133 [0.116, 0.149]",
    "lower"
   ],
   [
    "parameters",
    "150 796",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "36.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "unseen-heading",
  "title": "ffnn (acc, torch)"
 },
 "magneto-climb-small-v6__converge__unseen-heading__gnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--unseen-heading",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__unseen-heading__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "1.21 [1.18, 1.25]",
    "lower"
   ],
   [
    "cl_score",
    "0.0593 [0.0499, 0.0762]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.941 [0.920, 0.976]",
    "lower"
   ],
   [
    "equiv_err",
    "0.0269 [0.0191, 0.0405]",
    "lower"
   ],
   [
    "invar_change",
    "1.17 [0.20, 1.69]",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.317 [0.295, 0.358]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0853 [0.0796, 0.0906]",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "36.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "unseen-heading",
  "title": "gnn (acc, torch)"
 },
 "magneto-climb-small-v6__converge__unseen-heading__sdgnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--unseen-heading",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__unseen-heading__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2-3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0662 [0.0655, 0.0672]",
    "lower"
   ],
   [
    "cl_score",
    "0.704 [0.607, 0.818]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0516 [0.0510, 0.0524]",
    "lower"
   ],
   [
    "equiv_err",
    "3.72 × 10⁻⁷ [3.07 × 10⁻⁷, 4.36 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.167 [0.000, 0.333]",
    "higher"
   ],
   [
    "cl_held_s",
    "1.88 [1.65, 2.16]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0274 [0.0239, 0.0311]",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "36.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "unseen-heading",
  "title": "sdgnn (acc, torch)"
 },
 "magneto-climb-small-v6__converge__unseen-heading__sdnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--unseen-heading",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__unseen-heading__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0429 [0.0410, 0.0446]",
    "lower"
   ],
   [
    "cl_score",
    "0.684 [0.487, 0.827]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0335 [0.0319, 0.0347]",
    "lower"
   ],
   [
    "equiv_err",
    "2.45 × 10⁻⁷ [2.43 × 10⁻⁷, 2.47 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.222 [0.167, 0.333]",
    "higher"
   ],
   [
    "cl_held_s",
    "1.83 [1.35, 2.18]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0358 [0.0304, 0.0412]",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "36.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "unseen-heading",
  "title": "sdnn (acc, torch)"
 },
 "magneto-climb-small-v6__converge__unseen-rotation__ffnn-leg__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--unseen-rotation",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__unseen-rotation__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.897 [0.858, 0.929]",
    "lower"
   ],
   [
    "cl_score",
    "0.0900 [0.0844, 0.0984]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.702 [0.671, 0.727]",
    "lower"
   ],
   [
    "equiv_err",
    "1.22 [1.07, 1.35]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.397 [0.383, 0.417]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0721 [0.0702, 0.0748]",
    "lower"
   ],
   [
    "parameters",
    "158 988",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "8 833 [6 500, 10 000]",
    ""
   ],
   [
    "epochs",
    "65.3 [48.0, 74.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 1",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "unseen-rotation",
  "title": "ffnn-leg (acc, torch)"
 },
 "magneto-climb-small-v6__converge__unseen-rotation__ffnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--unseen-rotation",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__unseen-rotation__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "1.06 [1.05, 1.09]",
    "lower"
   ],
   [
    "cl_score",
    "0.0148 [0.0035, 0.0268]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.833 [0.822, 0.854]",
    "lower"
   ],
   [
    "equiv_err",
    "1.52 [1.49, 1.54]",
    "lower"
   ],
   [
    "invar_change",
    "1.37 [1.20, 1.51]",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.215 [0.187, 0.244]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0936 [0.0911, 0.0977]",
    "lower"
   ],
   [
    "parameters",
    "150 796",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "7 333 [6 500, 8 000]",
    ""
   ],
   [
    "epochs",
    "54.0 [48.0, 59.0]",
    ""
   ],
   [
    "stopped_by",
    "patience 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "unseen-rotation",
  "title": "ffnn (acc, torch)"
 },
 "magneto-climb-small-v6__converge__unseen-rotation__gnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--unseen-rotation",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__unseen-rotation__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.650 [0.593, 0.698]",
    "lower"
   ],
   [
    "cl_score",
    "0.0731 [0.0659, 0.0801]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.509 [0.464, 0.547]",
    "lower"
   ],
   [
    "equiv_err",
    "1.30 [1.25, 1.33]",
    "lower"
   ],
   [
    "invar_change",
    "1.46 [1.27, 1.63]",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.356 [0.338, 0.373]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0806 [0.0777, 0.0862]",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "9 333 [8 000, 10 000]",
    ""
   ],
   [
    "epochs",
    "69.0 [59.0, 74.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 1",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "unseen-rotation",
  "title": "gnn (acc, torch)"
 },
 "magneto-climb-small-v6__converge__unseen-rotation__sdgnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--unseen-rotation",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__unseen-rotation__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.172 [0.154, 0.191]",
    "lower"
   ],
   [
    "cl_score",
    "0.656 [0.523, 0.744]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.135 [0.121, 0.150]",
    "lower"
   ],
   [
    "equiv_err",
    "3.74 × 10⁻⁷ [3.71 × 10⁻⁷, 3.78 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.111 [0.000, 0.167]",
    "higher"
   ],
   [
    "cl_held_s",
    "1.77 [1.45, 1.98]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0368 [0.0331, 0.0435]",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "74.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "unseen-rotation",
  "title": "sdgnn (acc, torch)"
 },
 "magneto-climb-small-v6__converge__unseen-rotation__sdnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v6.html#converge--unseen-rotation",
  "dataset": "magneto-climb-small-v6",
  "entry": "entries/magneto-climb-small-v6__converge__unseen-rotation__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.117 [0.112, 0.121]",
    "lower"
   ],
   [
    "cl_score",
    "0.667 [0.604, 0.766]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0916 [0.0877, 0.0946]",
    "lower"
   ],
   [
    "equiv_err",
    "3.08 × 10⁻⁷ [2.47 × 10⁻⁷, 3.73 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.0556 [0.0000, 0.1667]",
    "higher"
   ],
   [
    "cl_held_s",
    "1.79 [1.64, 2.03]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0362 [0.0321, 0.0438]",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "74.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "unseen-rotation",
  "title": "sdnn (acc, torch)"
 },
 "nona-climb-small-v6__converge__fraction-0.1__ffnn-leg__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--fraction-0-1",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__fraction-0.1__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3-4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.218 [0.190, 0.248]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.365 [0.318, 0.413]",
    "lower"
   ],
   [
    "equiv_err",
    "1.22 [1.18, 1.28]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "192 283",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "9 333 [8 500, 10 000]",
    ""
   ],
   [
    "epochs",
    "139 [126, 149]",
    ""
   ],
   [
    "stopped_by",
    "patience 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.1",
  "title": "ffnn-leg (acc, torch)"
 },
 "nona-climb-small-v6__converge__fraction-0.1__ffnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--fraction-0-1",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__fraction-0.1__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.500 [0.490, 0.513]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.837 [0.817, 0.860]",
    "lower"
   ],
   [
    "equiv_err",
    "1.27 [1.24, 1.30]",
    "lower"
   ],
   [
    "invar_change",
    "1.26 [1.16, 1.38]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "168 731",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "7 833 [6 500, 10 000]",
    ""
   ],
   [
    "epochs",
    "117 [97, 149]",
    ""
   ],
   [
    "stopped_by",
    "budget 1, patience 2",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.1",
  "title": "ffnn (acc, torch)"
 },
 "nona-climb-small-v6__converge__fraction-0.1__gnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--fraction-0-1",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__fraction-0.1__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3-4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.187 [0.143, 0.233]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.313 [0.241, 0.388]",
    "lower"
   ],
   [
    "equiv_err",
    "0.947 [0.703, 1.313]",
    "lower"
   ],
   [
    "invar_change",
    "1.37 [1.29, 1.42]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "8 500 [5 500, 10 000]",
    ""
   ],
   [
    "epochs",
    "127 [82, 149]",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 1",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.1",
  "title": "gnn (acc, torch)"
 },
 "nona-climb-small-v6__converge__fraction-0.1__sdgnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--fraction-0-1",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__fraction-0.1__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0335 [0.0280, 0.0411]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0561 [0.0470, 0.0685]",
    "lower"
   ],
   [
    "equiv_err",
    "3.66 × 10⁻⁷ [3.19 × 10⁻⁷, 4.28 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "149",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.1",
  "title": "sdgnn (acc, torch)"
 },
 "nona-climb-small-v6__converge__fraction-0.1__sdnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--fraction-0-1",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__fraction-0.1__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0231 [0.0185, 0.0280]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0386 [0.0310, 0.0466]",
    "lower"
   ],
   [
    "equiv_err",
    "2.87 × 10⁻⁷ [2.71 × 10⁻⁷, 3.19 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "149",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.1",
  "title": "sdnn (acc, torch)"
 },
 "nona-climb-small-v6__converge__fraction-0.25__ffnn-leg__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--fraction-0-25",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__fraction-0.25__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.123 [0.078, 0.158]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.205 [0.130, 0.265]",
    "lower"
   ],
   [
    "equiv_err",
    "1.04 [0.80, 1.19]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "192 283",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "8 500 [7 000, 10 000]",
    ""
   ],
   [
    "epochs",
    "50.0 [41.0, 59.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 1, patience 2",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.25",
  "title": "ffnn-leg (acc, torch)"
 },
 "nona-climb-small-v6__converge__fraction-0.25__ffnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--fraction-0-25",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__fraction-0.25__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.315 [0.232, 0.366]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.527 [0.389, 0.615]",
    "lower"
   ],
   [
    "equiv_err",
    "1.22 [1.11, 1.35]",
    "lower"
   ],
   [
    "invar_change",
    "1.21 [1.12, 1.26]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "168 731",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "6 000 [4 500, 7 000]",
    ""
   ],
   [
    "epochs",
    "35.0 [26.0, 41.0]",
    ""
   ],
   [
    "stopped_by",
    "patience 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.25",
  "title": "ffnn (acc, torch)"
 },
 "nona-climb-small-v6__converge__fraction-0.25__gnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--fraction-0-25",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__fraction-0.25__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1-3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0574 [0.0286, 0.0985]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0961 [0.0479, 0.1655]",
    "lower"
   ],
   [
    "equiv_err",
    "0.513 [0.368, 0.619]",
    "lower"
   ],
   [
    "invar_change",
    "1.12 [1.06, 1.20]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "59.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.25",
  "title": "gnn (acc, torch)"
 },
 "nona-climb-small-v6__converge__fraction-0.25__sdgnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--fraction-0-25",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__fraction-0.25__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2-3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0142 [0.0125, 0.0151]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0238 [0.0208, 0.0254]",
    "lower"
   ],
   [
    "equiv_err",
    "3.06 × 10⁻⁷ [2.70 × 10⁻⁷, 3.26 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "59.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.25",
  "title": "sdgnn (acc, torch)"
 },
 "nona-climb-small-v6__converge__fraction-0.25__sdnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--fraction-0-25",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__fraction-0.25__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1-2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.00946 [0.00823, 0.01081]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0158 [0.0137, 0.0181]",
    "lower"
   ],
   [
    "equiv_err",
    "3.23 × 10⁻⁷ [3.21 × 10⁻⁷, 3.24 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "59.0",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 1",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.25",
  "title": "sdnn (acc, torch)"
 },
 "nona-climb-small-v6__converge__fraction-0.5__ffnn-leg__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--fraction-0-5",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__fraction-0.5__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0522 [0.0427, 0.0706]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0873 [0.0717, 0.1176]",
    "lower"
   ],
   [
    "equiv_err",
    "0.830 [0.681, 0.998]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "192 283",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "30.0",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 1",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.5",
  "title": "ffnn-leg (acc, torch)"
 },
 "nona-climb-small-v6__converge__fraction-0.5__ffnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--fraction-0-5",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__fraction-0.5__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.134 [0.106, 0.160]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.224 [0.177, 0.266]",
    "lower"
   ],
   [
    "equiv_err",
    "0.946 [0.848, 1.008]",
    "lower"
   ],
   [
    "invar_change",
    "1.19 [1.10, 1.31]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "168 731",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "9 500 [8 500, 10 000]",
    ""
   ],
   [
    "epochs",
    "28.3 [25.0, 30.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 1",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.5",
  "title": "ffnn (acc, torch)"
 },
 "nona-climb-small-v6__converge__fraction-0.5__gnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--fraction-0-5",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__fraction-0.5__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2-3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0209 [0.0201, 0.0224]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0349 [0.0337, 0.0373]",
    "lower"
   ],
   [
    "equiv_err",
    "0.490 [0.377, 0.683]",
    "lower"
   ],
   [
    "invar_change",
    "1.24 [1.13, 1.32]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "30.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.5",
  "title": "gnn (acc, torch)"
 },
 "nona-climb-small-v6__converge__fraction-0.5__sdgnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--fraction-0-5",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__fraction-0.5__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2-3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0143 [0.0128, 0.0155]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0239 [0.0213, 0.0261]",
    "lower"
   ],
   [
    "equiv_err",
    "3.06 × 10⁻⁷ [2.71 × 10⁻⁷, 3.23 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "30.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.5",
  "title": "sdgnn (acc, torch)"
 },
 "nona-climb-small-v6__converge__fraction-0.5__sdnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--fraction-0-5",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__fraction-0.5__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.00968 [0.00912, 0.01018]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0162 [0.0152, 0.0171]",
    "lower"
   ],
   [
    "equiv_err",
    "2.88 × 10⁻⁷ [2.68 × 10⁻⁷, 3.27 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "30.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.5",
  "title": "sdnn (acc, torch)"
 },
 "nona-climb-small-v6__converge__fraction-0.75__ffnn-leg__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--fraction-0-75",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__fraction-0.75__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3-4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0356 [0.0323, 0.0388]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0595 [0.0542, 0.0652]",
    "lower"
   ],
   [
    "equiv_err",
    "0.484 [0.416, 0.541]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "192 283",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "20.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.75",
  "title": "ffnn-leg (acc, torch)"
 },
 "nona-climb-small-v6__converge__fraction-0.75__ffnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--fraction-0-75",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__fraction-0.75__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0826 [0.0783, 0.0900]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.138 [0.131, 0.151]",
    "lower"
   ],
   [
    "equiv_err",
    "0.910 [0.625, 1.062]",
    "lower"
   ],
   [
    "invar_change",
    "1.12 [1.06, 1.16]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "168 731",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "20.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.75",
  "title": "ffnn (acc, torch)"
 },
 "nona-climb-small-v6__converge__fraction-0.75__gnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--fraction-0-75",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__fraction-0.75__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3-4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0256 [0.0211, 0.0336]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0430 [0.0352, 0.0565]",
    "lower"
   ],
   [
    "equiv_err",
    "0.421 [0.353, 0.519]",
    "lower"
   ],
   [
    "invar_change",
    "1.23 [1.11, 1.33]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "8 667 [6 000, 10 000]",
    ""
   ],
   [
    "epochs",
    "17.3 [12.0, 20.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 1",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.75",
  "title": "gnn (acc, torch)"
 },
 "nona-climb-small-v6__converge__fraction-0.75__sdgnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--fraction-0-75",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__fraction-0.75__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0148 [0.0142, 0.0158]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0248 [0.0238, 0.0265]",
    "lower"
   ],
   [
    "equiv_err",
    "3.22 × 10⁻⁷ [3.19 × 10⁻⁷, 3.27 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "20.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.75",
  "title": "sdgnn (acc, torch)"
 },
 "nona-climb-small-v6__converge__fraction-0.75__sdnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--fraction-0-75",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__fraction-0.75__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0108 [0.0101, 0.0115]",
    "lower"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0181 [0.0169, 0.0193]",
    "lower"
   ],
   [
    "equiv_err",
    "3.20 × 10⁻⁷ [3.20 × 10⁻⁷, 3.21 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "9 000 [7 500, 10 000]",
    ""
   ],
   [
    "epochs",
    "18.0 [15.0, 20.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 1, patience 2",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.75",
  "title": "sdnn (acc, torch)"
 },
 "nona-climb-small-v6__converge__iid__ffnn-leg__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--iid",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__iid__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0328 [0.0306, 0.0342]",
    "lower"
   ],
   [
    "cl_score",
    "0.645 [0.586, 0.679]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0549 [0.0512, 0.0570]",
    "lower"
   ],
   [
    "equiv_err",
    "0.408 [0.387, 0.422]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.333",
    "higher"
   ],
   [
    "cl_held_s",
    "1.77 [1.63, 1.85]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0440 [0.0346, 0.0591]",
    "lower"
   ],
   [
    "parameters",
    "192 283",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "15.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "iid",
  "title": "ffnn-leg (acc, torch)"
 },
 "nona-climb-small-v6__converge__iid__ffnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--iid",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__iid__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0693 [0.0633, 0.0792]",
    "lower"
   ],
   [
    "cl_score",
    "0.601 [0.542, 0.704]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.116 [0.105, 0.133]",
    "lower"
   ],
   [
    "equiv_err",
    "1.01 [0.81, 1.18]",
    "lower"
   ],
   [
    "invar_change",
    "1.19 [1.10, 1.31]",
    "lower"
   ],
   [
    "cl_success",
    "0.222 [0.167, 0.333]",
    "higher"
   ],
   [
    "cl_held_s",
    "1.67 [1.53, 1.91]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0634 [0.0404, 0.0796]",
    "lower"
   ],
   [
    "parameters",
    "168 731",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "15.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "iid",
  "title": "ffnn (acc, torch)"
 },
 "nona-climb-small-v6__converge__iid__gnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--iid",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__iid__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2-3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0206 [0.0186, 0.0237]",
    "lower"
   ],
   [
    "cl_score",
    "0.897 [0.777, 0.997]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0345 [0.0311, 0.0395]",
    "lower"
   ],
   [
    "equiv_err",
    "0.310 [0.121, 0.603]",
    "lower"
   ],
   [
    "invar_change",
    "1.28 [1.08, 1.56]",
    "lower"
   ],
   [
    "cl_success",
    "0.611 [0.167, 0.833]",
    "higher"
   ],
   [
    "cl_held_s",
    "2.36 [2.08, 2.59]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0404 [0.0252, 0.0545]",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "9 000 [7 000, 10 000]",
    ""
   ],
   [
    "epochs",
    "13.3 [10.0, 15.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 1",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "iid",
  "title": "gnn (acc, torch)"
 },
 "nona-climb-small-v6__converge__iid__sdgnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--iid",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__iid__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2-3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0148 [0.0130, 0.0164]",
    "lower"
   ],
   [
    "cl_score",
    "1.00",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0247 [0.0216, 0.0276]",
    "lower"
   ],
   [
    "equiv_err",
    "3.31 × 10⁻⁷ [3.19 × 10⁻⁷, 3.49 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "1.00",
    "higher"
   ],
   [
    "cl_held_s",
    "2.60",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.00851 [0.00625, 0.01001]",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "15.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "iid",
  "title": "sdgnn (acc, torch)"
 },
 "nona-climb-small-v6__converge__iid__sdnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--iid",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__iid__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.00927 [0.00859, 0.01009]",
    "lower"
   ],
   [
    "cl_score",
    "1.00",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0155 [0.0144, 0.0168]",
    "lower"
   ],
   [
    "equiv_err",
    "3.24 × 10⁻⁷ [3.23 × 10⁻⁷, 3.25 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "1.00",
    "higher"
   ],
   [
    "cl_held_s",
    "2.60",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.00990 [0.00766, 0.01124]",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "15.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "iid",
  "title": "sdnn (acc, torch)"
 },
 "nona-climb-small-v6__converge__orbit-rotation__ffnn-leg__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--orbit-rotation",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__orbit-rotation__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.682 [0.670, 0.700]",
    "lower"
   ],
   [
    "cl_score",
    "0.330 [0.306, 0.352]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "1.14 [1.12, 1.17]",
    "lower"
   ],
   [
    "equiv_err",
    "1.54 [1.49, 1.58]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "1.03 [0.98, 1.08]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.126 [0.123, 0.128]",
    "lower"
   ],
   [
    "parameters",
    "192 283",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "106",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "orbit-rotation",
  "title": "ffnn-leg (acc, torch)"
 },
 "nona-climb-small-v6__converge__orbit-rotation__ffnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--orbit-rotation",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__orbit-rotation__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.783 [0.781, 0.785]",
    "lower"
   ],
   [
    "cl_score",
    "0.328 [0.318, 0.333]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "1.31 [1.31, 1.31]",
    "lower"
   ],
   [
    "equiv_err",
    "1.42 [1.37, 1.45]",
    "lower"
   ],
   [
    "invar_change",
    "0.988 [0.891, 1.061]",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "1.03 [1.00, 1.04]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.150 [0.145, 0.159]",
    "lower"
   ],
   [
    "parameters",
    "168 731",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "9 500 [9 000, 10 000]",
    ""
   ],
   [
    "epochs",
    "101 [95, 106]",
    ""
   ],
   [
    "stopped_by",
    "budget 1, patience 2",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "orbit-rotation",
  "title": "ffnn (acc, torch)"
 },
 "nona-climb-small-v6__converge__orbit-rotation__gnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--orbit-rotation",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__orbit-rotation__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.390 [0.354, 0.423]",
    "lower"
   ],
   [
    "cl_score",
    "0.772 [0.538, 0.990]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.654 [0.594, 0.709]",
    "lower"
   ],
   [
    "equiv_err",
    "1.27 [1.15, 1.42]",
    "lower"
   ],
   [
    "invar_change",
    "0.968 [0.922, 1.030]",
    "lower"
   ],
   [
    "cl_success",
    "0.278 [0.000, 0.500]",
    "higher"
   ],
   [
    "cl_held_s",
    "2.07 [1.52, 2.58]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0982 [0.0693, 0.1327]",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "106",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "orbit-rotation",
  "title": "gnn (acc, torch)"
 },
 "nona-climb-small-v6__converge__orbit-rotation__sdgnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--orbit-rotation",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__orbit-rotation__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0137 [0.0122, 0.0148]",
    "lower"
   ],
   [
    "cl_score",
    "1.00",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0230 [0.0204, 0.0248]",
    "lower"
   ],
   [
    "equiv_err",
    "3.20 × 10⁻⁷ [3.18 × 10⁻⁷, 3.21 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "1.00",
    "higher"
   ],
   [
    "cl_held_s",
    "2.60",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0145 [0.0123, 0.0166]",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "106",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "orbit-rotation",
  "title": "sdgnn (acc, torch)"
 },
 "nona-climb-small-v6__converge__orbit-rotation__sdnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--orbit-rotation",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__orbit-rotation__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.00811 [0.00745, 0.00865]",
    "lower"
   ],
   [
    "cl_score",
    "0.811 [0.615, 1.000]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0136 [0.0125, 0.0145]",
    "lower"
   ],
   [
    "equiv_err",
    "2.97 × 10⁻⁷ [2.70 × 10⁻⁷, 3.23 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.556 [0.167, 1.000]",
    "higher"
   ],
   [
    "cl_held_s",
    "2.16 [1.70, 2.60]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0227 [0.0155, 0.0281]",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "106",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "orbit-rotation",
  "title": "sdnn (acc, torch)"
 },
 "nona-climb-small-v6__converge__unseen-heading__ffnn-leg__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--unseen-heading",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__unseen-heading__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0291 [0.0285, 0.0298]",
    "lower"
   ],
   [
    "cl_score",
    "0.705 [0.585, 0.898]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0488 [0.0478, 0.0500]",
    "lower"
   ],
   [
    "equiv_err",
    "0.393 [0.340, 0.466]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.222 [0.000, 0.500]",
    "higher"
   ],
   [
    "cl_held_s",
    "1.91 [1.63, 2.36]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0515 [0.0412, 0.0607]",
    "lower"
   ],
   [
    "parameters",
    "192 283",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "24.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "unseen-heading",
  "title": "ffnn-leg (acc, torch)"
 },
 "nona-climb-small-v6__converge__unseen-heading__ffnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--unseen-heading",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__unseen-heading__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4-5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.632 [0.628, 0.635]",
    "lower"
   ],
   [
    "cl_score",
    "-0.0238 [-0.0340, -0.0132]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "1.06 [1.05, 1.06]",
    "lower"
   ],
   [
    "equiv_err",
    "1.61 [1.47, 1.75]",
    "lower"
   ],
   [
    "invar_change",
    "1.08 [0.14, 1.58]",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.204 [0.180, 0.228]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.106 [0.101, 0.110]",
    "lower"
   ],
   [
    "parameters",
    "168 731",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "24.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "unseen-heading",
  "title": "ffnn (acc, torch)"
 },
 "nona-climb-small-v6__converge__unseen-heading__gnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--unseen-heading",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__unseen-heading__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4-5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.609 [0.524, 0.775]",
    "lower"
   ],
   [
    "cl_score",
    "0.382 [0.274, 0.505]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "1.02 [0.88, 1.30]",
    "lower"
   ],
   [
    "equiv_err",
    "0.0111 [0.0080, 0.0156]",
    "lower"
   ],
   [
    "invar_change",
    "1.01 [0.39, 1.42]",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "1.15 [0.90, 1.44]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.122 [0.115, 0.132]",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "9 000 [8 000, 9 500]",
    ""
   ],
   [
    "epochs",
    "21.7 [19.0, 23.0]",
    ""
   ],
   [
    "stopped_by",
    "patience 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "unseen-heading",
  "title": "gnn (acc, torch)"
 },
 "nona-climb-small-v6__converge__unseen-heading__sdgnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--unseen-heading",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__unseen-heading__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1-2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0134 [0.0124, 0.0145]",
    "lower"
   ],
   [
    "cl_score",
    "0.999 [0.997, 1.000]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0224 [0.0207, 0.0244]",
    "lower"
   ],
   [
    "equiv_err",
    "3.22 × 10⁻⁷ [3.19 × 10⁻⁷, 3.25 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.944 [0.833, 1.000]",
    "higher"
   ],
   [
    "cl_held_s",
    "2.60 [2.59, 2.60]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.00899 [0.00522, 0.01111]",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "24.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "unseen-heading",
  "title": "sdgnn (acc, torch)"
 },
 "nona-climb-small-v6__converge__unseen-heading__sdnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--unseen-heading",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__unseen-heading__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1-2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0108 [0.0084, 0.0138]",
    "lower"
   ],
   [
    "cl_score",
    "0.998 [0.993, 1.000]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0181 [0.0141, 0.0231]",
    "lower"
   ],
   [
    "equiv_err",
    "3.22 × 10⁻⁷ [2.66 × 10⁻⁷, 3.79 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.889 [0.667, 1.000]",
    "higher"
   ],
   [
    "cl_held_s",
    "2.59 [2.58, 2.60]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.00875 [0.00774, 0.00980]",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "8 833 [6 500, 10 000]",
    ""
   ],
   [
    "epochs",
    "21.0 [15.0, 24.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 1",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "unseen-heading",
  "title": "sdnn (acc, torch)"
 },
 "nona-climb-small-v6__converge__unseen-rotation__ffnn-leg__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--unseen-rotation",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__unseen-rotation__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.751 [0.744, 0.764]",
    "lower"
   ],
   [
    "cl_score",
    "0.394 [0.356, 0.426]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "1.25 [1.24, 1.28]",
    "lower"
   ],
   [
    "equiv_err",
    "1.83 [1.71, 2.05]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "1.18 [1.09, 1.25]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.137 [0.135, 0.137]",
    "lower"
   ],
   [
    "parameters",
    "192 283",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "9 667 [9 000, 10 000]",
    ""
   ],
   [
    "epochs",
    "205 [191, 212]",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 1",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "unseen-rotation",
  "title": "ffnn-leg (acc, torch)"
 },
 "nona-climb-small-v6__converge__unseen-rotation__ffnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--unseen-rotation",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__unseen-rotation__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.798 [0.791, 0.803]",
    "lower"
   ],
   [
    "cl_score",
    "0.284 [0.259, 0.324]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "1.33 [1.32, 1.34]",
    "lower"
   ],
   [
    "equiv_err",
    "1.53 [1.47, 1.62]",
    "lower"
   ],
   [
    "invar_change",
    "1.07 [0.99, 1.12]",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.919 [0.861, 1.012]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.145 [0.137, 0.153]",
    "lower"
   ],
   [
    "parameters",
    "168 731",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "6 333 [4 000, 10 000]",
    ""
   ],
   [
    "epochs",
    "134 [85, 212]",
    ""
   ],
   [
    "stopped_by",
    "budget 1, patience 2",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "unseen-rotation",
  "title": "ffnn (acc, torch)"
 },
 "nona-climb-small-v6__converge__unseen-rotation__gnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--unseen-rotation",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__unseen-rotation__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.389 [0.366, 0.407]",
    "lower"
   ],
   [
    "cl_score",
    "0.804 [0.728, 0.910]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.650 [0.611, 0.680]",
    "lower"
   ],
   [
    "equiv_err",
    "1.16 [1.10, 1.23]",
    "lower"
   ],
   [
    "invar_change",
    "1.14 [1.09, 1.21]",
    "lower"
   ],
   [
    "cl_success",
    "0.389 [0.167, 0.667]",
    "higher"
   ],
   [
    "cl_held_s",
    "2.14 [1.96, 2.39]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0836 [0.0474, 0.1418]",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "8 667 [6 000, 10 000]",
    ""
   ],
   [
    "epochs",
    "184 [127, 212]",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 1",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "unseen-rotation",
  "title": "gnn (acc, torch)"
 },
 "nona-climb-small-v6__converge__unseen-rotation__sdgnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--unseen-rotation",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__unseen-rotation__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0313 [0.0283, 0.0332]",
    "lower"
   ],
   [
    "cl_score",
    "0.822 [0.649, 0.997]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0523 [0.0472, 0.0555]",
    "lower"
   ],
   [
    "equiv_err",
    "3.21 × 10⁻⁷ [3.13 × 10⁻⁷, 3.32 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.611 [0.500, 0.833]",
    "higher"
   ],
   [
    "cl_held_s",
    "2.18 [1.78, 2.59]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0324 [0.0139, 0.0683]",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "9 833 [9 500, 10 000]",
    ""
   ],
   [
    "epochs",
    "209 [202, 212]",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 1",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "unseen-rotation",
  "title": "sdgnn (acc, torch)"
 },
 "nona-climb-small-v6__converge__unseen-rotation__sdnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#converge--unseen-rotation",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__converge__unseen-rotation__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0198 [0.0193, 0.0203]",
    "lower"
   ],
   [
    "cl_score",
    "0.752 [0.297, 0.997]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0330 [0.0322, 0.0339]",
    "lower"
   ],
   [
    "equiv_err",
    "3.23 × 10⁻⁷ [3.22 × 10⁻⁷, 3.25 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.556 [0.000, 0.833]",
    "higher"
   ],
   [
    "cl_held_s",
    "2.02 [0.95, 2.59]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0237 [0.0202, 0.0262]",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "212",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 1",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "unseen-rotation",
  "title": "sdnn (acc, torch)"
 },
 "nona-climb-small-v6__cosine__iid__ffnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#cosine--iid",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__cosine__iid__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0608 [0.0509, 0.0760]",
    "lower"
   ],
   [
    "cl_score",
    "0.595 [0.544, 0.663]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.102 [0.085, 0.128]",
    "lower"
   ],
   [
    "equiv_err",
    "1.03 [0.78, 1.17]",
    "lower"
   ],
   [
    "invar_change",
    "1.15 [1.11, 1.21]",
    "lower"
   ],
   [
    "cl_success",
    "0.167 [0.000, 0.333]",
    "higher"
   ],
   [
    "cl_held_s",
    "1.65 [1.53, 1.81]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0535 [0.0422, 0.0601]",
    "lower"
   ],
   [
    "parameters",
    "168 731",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "15.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "cosine",
  "robot": "nona",
  "split": "iid",
  "title": "ffnn (acc, torch)"
 },
 "nona-climb-small-v6__cosine__iid__sdnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#cosine--iid",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__cosine__iid__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.00449 [0.00434, 0.00463]",
    "lower"
   ],
   [
    "cl_score",
    "1.00",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.00752 [0.00722, 0.00776]",
    "lower"
   ],
   [
    "equiv_err",
    "3.22 × 10⁻⁷ [3.21 × 10⁻⁷, 3.23 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "1.00",
    "higher"
   ],
   [
    "cl_held_s",
    "2.60",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.00203 [0.00186, 0.00213]",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "15.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "cosine",
  "robot": "nona",
  "split": "iid",
  "title": "sdnn (acc, torch)"
 },
 "nona-climb-small-v6__cosine__unseen-rotation__ffnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#cosine--unseen-rotation",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__cosine__unseen-rotation__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.798 [0.791, 0.803]",
    "lower"
   ],
   [
    "cl_score",
    "0.284 [0.261, 0.305]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "1.33 [1.32, 1.34]",
    "lower"
   ],
   [
    "equiv_err",
    "1.49 [1.45, 1.52]",
    "lower"
   ],
   [
    "invar_change",
    "1.03 [0.98, 1.08]",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.919 [0.864, 0.969]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.140 [0.139, 0.142]",
    "lower"
   ],
   [
    "parameters",
    "168 731",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "8 000 [4 000, 10 000]",
    ""
   ],
   [
    "epochs",
    "170 [85, 212]",
    ""
   ],
   [
    "stopped_by",
    "budget 1, patience 2",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "cosine",
  "robot": "nona",
  "split": "unseen-rotation",
  "title": "ffnn (acc, torch)"
 },
 "nona-climb-small-v6__cosine__unseen-rotation__sdnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v6.html#cosine--unseen-rotation",
  "dataset": "nona-climb-small-v6",
  "entry": "entries/nona-climb-small-v6__cosine__unseen-rotation__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0191 [0.0189, 0.0193]",
    "lower"
   ],
   [
    "cl_score",
    "0.933 [0.899, 0.960]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0319 [0.0315, 0.0321]",
    "lower"
   ],
   [
    "equiv_err",
    "3.57 × 10⁻⁷ [3.21 × 10⁻⁷, 4.30 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.778 [0.667, 0.833]",
    "higher"
   ],
   [
    "cl_held_s",
    "2.44 [2.36, 2.51]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0270 [0.0253, 0.0292]",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "212",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "cosine",
  "robot": "nona",
  "split": "unseen-rotation",
  "title": "sdnn (acc, torch)"
 }
};
