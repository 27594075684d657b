window.SYMBENCH_ENTRIES = {
 "hexa-climb-small-v7__converge__iid__ffnn-leg__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--iid",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__iid__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.105 [0.099, 0.111]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.447 [0.429, 0.469]",
    "higher"
   ],
   [
    "cl_score",
    "0.529 [0.492, 0.567]",
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
    "0.134 [0.127, 0.142]",
    "lower"
   ],
   [
    "equiv_err",
    "0.734 [0.688, 0.770]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.175 [0.125, 0.231]",
    "higher"
   ],
   [
    "cl_held_s",
    "1.18 [1.11, 1.25]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0399 [0.0370, 0.0426]",
    "lower"
   ],
   [
    "parameters",
    "172 306",
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
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "iid",
  "title": "ffnn-leg (acc, torch)"
 },
 "hexa-climb-small-v7__converge__iid__ffnn-leg__acc__torch__matched-100000": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--matched-100000--iid",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__iid__ffnn-leg__acc__torch__matched-100000.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.107 [0.101, 0.113]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
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
    "0.137 [0.129, 0.145]",
    "lower"
   ],
   [
    "equiv_err",
    "0.984 [0.908, 1.059]",
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
    "100 063",
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
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "iid",
  "title": "ffnn-leg (acc, torch), matched at 100 000 parameters"
 },
 "hexa-climb-small-v7__converge__iid__ffnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--iid",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__iid__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4-5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.224 [0.208, 0.242]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.327 [0.317, 0.338]",
    "higher"
   ],
   [
    "cl_score",
    "0.411 [0.394, 0.430]",
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
    "0.286 [0.266, 0.308]",
    "lower"
   ],
   [
    "equiv_err",
    "1.10 [0.93, 1.27]",
    "lower"
   ],
   [
    "invar_change",
    "1.41 [1.36, 1.46]",
    "lower"
   ],
   [
    "cl_success",
    "0.0125 [0.0000, 0.0250]",
    "higher"
   ],
   [
    "cl_held_s",
    "0.971 [0.941, 1.009]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0561 [0.0514, 0.0605]",
    "lower"
   ],
   [
    "parameters",
    "157 970",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "9 200 [7 800, 10 000]",
    ""
   ],
   [
    "epochs",
    "15.6 [13.2, 17.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 3, patience 2",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "iid",
  "title": "ffnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__iid__ffnn__acc__torch__matched-100000": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--matched-100000--iid",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__iid__ffnn__acc__torch__matched-100000.html",
  "metrics": [
   [
    "rank",
    "4-5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.230 [0.213, 0.248]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
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
    "0.294 [0.273, 0.316]",
    "lower"
   ],
   [
    "equiv_err",
    "1.20 [0.98, 1.41]",
    "lower"
   ],
   [
    "invar_change",
    "1.37 [1.26, 1.49]",
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
    "100 115",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 4, patience 1",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "iid",
  "title": "ffnn (acc, torch), matched at 100 000 parameters"
 },
 "hexa-climb-small-v7__converge__iid__gnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--iid",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__iid__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4-5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.211 [0.205, 0.218]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.227 [0.190, 0.265]",
    "higher"
   ],
   [
    "cl_score",
    "0.305 [0.259, 0.349]",
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
    "0.269 [0.263, 0.278]",
    "lower"
   ],
   [
    "equiv_err",
    "0.980 [0.641, 1.324]",
    "lower"
   ],
   [
    "invar_change",
    "1.60 [1.44, 1.74]",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.786 [0.708, 0.861]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0689 [0.0640, 0.0729]",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.009",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "iid",
  "title": "gnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__iid__gnn__acc__torch__matched-100000": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--matched-100000--iid",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__iid__gnn__acc__torch__matched-100000.html",
  "metrics": [
   [
    "rank",
    "4-5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.209 [0.194, 0.220]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
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
    "0.266 [0.248, 0.280]",
    "lower"
   ],
   [
    "equiv_err",
    "0.836 [0.695, 1.009]",
    "lower"
   ],
   [
    "invar_change",
    "1.56 [1.41, 1.76]",
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
    "99 381",
    ""
   ],
   [
    "learning_rate",
    "0.009",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "iid",
  "title": "gnn (acc, torch), matched at 100 000 parameters"
 },
 "hexa-climb-small-v7__converge__iid__sdgnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--iid",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__iid__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0567 [0.0530, 0.0601]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.517 [0.486, 0.542]",
    "higher"
   ],
   [
    "cl_score",
    "0.591 [0.541, 0.637]",
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
    "0.0724 [0.0678, 0.0766]",
    "lower"
   ],
   [
    "equiv_err",
    "4.20 × 10⁻⁷ [3.81 × 10⁻⁷, 4.59 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.244 [0.169, 0.294]",
    "higher"
   ],
   [
    "cl_held_s",
    "1.29 [1.20, 1.36]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0345 [0.0312, 0.0383]",
    "lower"
   ],
   [
    "parameters",
    "45 619",
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
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "iid",
  "title": "sdgnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__iid__sdgnn__acc__torch__matched-100000": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--matched-100000--iid",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__iid__sdgnn__acc__torch__matched-100000.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0517 [0.0491, 0.0543]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
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
    "0.0660 [0.0628, 0.0693]",
    "lower"
   ],
   [
    "equiv_err",
    "4.44 × 10⁻⁷ [3.68 × 10⁻⁷, 5.40 × 10⁻⁷]",
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
    "100 299",
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
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "iid",
  "title": "sdgnn (acc, torch), matched at 100 000 parameters"
 },
 "hexa-climb-small-v7__converge__iid__sdnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--iid",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__iid__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0458 [0.0431, 0.0487]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.559 [0.533, 0.585]",
    "higher"
   ],
   [
    "cl_score",
    "0.648 [0.613, 0.681]",
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
    "0.0585 [0.0551, 0.0620]",
    "lower"
   ],
   [
    "equiv_err",
    "3.91 × 10⁻⁷ [3.54 × 10⁻⁷, 4.44 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.325 [0.269, 0.381]",
    "higher"
   ],
   [
    "cl_held_s",
    "1.38 [1.32, 1.44]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0363 [0.0330, 0.0395]",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0135",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "iid",
  "title": "sdnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__iid__sdnn__acc__torch__matched-100000": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--matched-100000--iid",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__iid__sdnn__acc__torch__matched-100000.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0479 [0.0456, 0.0506]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
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
    "0.0611 [0.0583, 0.0645]",
    "lower"
   ],
   [
    "equiv_err",
    "4.04 × 10⁻⁷ [3.66 × 10⁻⁷, 4.43 × 10⁻⁷]",
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
    "99 810",
    ""
   ],
   [
    "learning_rate",
    "0.0135",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "iid",
  "title": "sdnn (acc, torch), matched at 100 000 parameters"
 }
};
