<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>QObject</name>
    <message>
        <source>Writing the demo study (aaa phantom)...</source>
        <translation>正在写入演示研究（AAA 体模）...</translation>
    </message>
    <message>
        <source>Rename &quot;%1&quot;</source>
        <translation>重命名“%1”</translation>
    </message>
    <message>
        <source>Name segment %1 &quot;%2&quot;</source>
        <translation>命名段 %1“%2”</translation>
    </message>
    <message>
        <source>Delete &quot;%1&quot;</source>
        <translation>删除“%1”</translation>
    </message>
    <message>
        <source>cannot be placed</source>
        <translation>无法放置</translation>
    </message>
    <message>
        <source>Paint label</source>
        <translation>绘制标签</translation>
    </message>
    <message>
        <source>Erase label</source>
        <translation>擦除标签</translation>
    </message>
    <message>
        <source>Remove island</source>
        <translation>移除孤岛</translation>
    </message>
</context>
<context>
    <name>Report</name>
    <message>
        <source>(not recorded)</source>
        <translation>（未记录）</translation>
    </message>
    <message>
        <source>Patient</source>
        <translation>患者</translation>
    </message>
    <message>
        <source>anonymized</source>
        <translation>已匿名</translation>
    </message>
    <message>
        <source>Patient ID</source>
        <translation>患者 ID</translation>
    </message>
    <message>
        <source>Birth date</source>
        <translation>出生日期</translation>
    </message>
    <message>
        <source>Institution</source>
        <translation>机构</translation>
    </message>
    <message>
        <source>Study date</source>
        <translation>检查日期</translation>
    </message>
    <message>
        <source>Study</source>
        <translation>检查</translation>
    </message>
    <message>
        <source>Series</source>
        <translation>序列</translation>
    </message>
    <message>
        <source>Software</source>
        <translation>软件</translation>
    </message>
    <message>
        <source>Report date</source>
        <translation>报告日期</translation>
    </message>
    <message>
        <source>Analyses not run</source>
        <translation>未进行的分析</translation>
    </message>
    <message>
        <source>planning support, needs clinical judgement</source>
        <translation>规划辅助，需结合临床判断</translation>
    </message>
    <message>
        <source>page %1</source>
        <translation>第 %1 页</translation>
    </message>
    <message>
        <source>Metric</source>
        <translation>指标</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>数值</translation>
    </message>
    <message>
        <source>Results are computed from the patient&apos;s images by physical models for planning support only. They are not a diagnosis and need clinical judgement.</source>
        <translation>结果由物理模型根据患者影像计算，仅供规划参考。它们不构成诊断，需结合临床判断。</translation>
    </message>
    <message>
        <source>Measurements marked for the report on the workstation. Points in the patient frame (LPS, mm).</source>
        <translation>在工作站上标记为纳入报告的测量。点位于患者坐标系（LPS，mm）。</translation>
    </message>
    <message>
        <source>Measurement</source>
        <translation>测量</translation>
    </message>
    <message>
        <source>Figure</source>
        <translation>数值</translation>
    </message>
    <message>
        <source>Definition</source>
        <translation>定义</translation>
    </message>
    <message>
        <source>Points [mm]</source>
        <translation>点 [mm]</translation>
    </message>
    <message>
        <source>Measurements</source>
        <translation>测量</translation>
    </message>
    <message>
        <source>Filling of the tree downstream of the tip</source>
        <translation>导管尖端下游血管树的充盈</translation>
    </message>
    <message>
        <source>Time from the start of the injection [s]</source>
        <translation>自注射开始的时间 [s]</translation>
    </message>
    <message>
        <source>Volume filled by the drug [%]</source>
        <translation>药物充盈的容积 [%]</translation>
    </message>
    <message>
        <source>filled</source>
        <translation>已充盈</translation>
    </message>
    <message>
        <source>Drug flow per branch (segments downstream of the tip, largest flow first)</source>
        <translation>各分支的药物流量（尖端下游的血管段，流量从大到小）</translation>
    </message>
    <message>
        <source>Segment</source>
        <translation>血管段</translation>
    </message>
    <message>
        <source>Nodes</source>
        <translation>节点</translation>
    </message>
    <message>
        <source>Radius [mm]</source>
        <translation>半径 [mm]</translation>
    </message>
    <message>
        <source>Length [mm]</source>
        <translation>长度 [mm]</translation>
    </message>
    <message>
        <source>Drug flow [ml/min]</source>
        <translation>药物流量 [ml/min]</translation>
    </message>
    <message>
        <source>Share [%]</source>
        <translation>占比 [%]</translation>
    </message>
    <message>
        <source>Filled after [s]</source>
        <translation>充盈时间 [s]</translation>
    </message>
    <message>
        <source>never</source>
        <translation>从未</translation>
    </message>
    <message>
        <source>%1 more</source>
        <translation>另有 %1 个</translation>
    </message>
    <message>
        <source>Chemoembolization: drug delivery through the hepatic arteries</source>
        <translation>化疗栓塞：经肝动脉的药物输送</translation>
    </message>
    <message>
        <source>sphere x,y,z,radius %1 mm</source>
        <translation>球体 x,y,z,半径 %1 mm</translation>
    </message>
    <message>
        <source>label %1</source>
        <translation>标签 %1</translation>
    </message>
    <message>
        <source>none given</source>
        <translation>未给出</translation>
    </message>
    <message>
        <source>Catheter tip: %1 (a node of the network, or a point x,y,z in mm, patient LPS). Tumour: %2. Blood enters at: %3.</source>
        <translation>导管尖端：%1（网络中的一个节点，或以 mm 表示的点 x,y,z，患者 LPS）。肿瘤：%2。血流入口：%3。</translation>
    </message>
    <message>
        <source>the root of the tree</source>
        <translation>血管树的根部</translation>
    </message>
    <message>
        <source>the tree&apos;s largest end</source>
        <translation>血管树最粗的末端</translation>
    </message>
    <message>
        <source>Feeders added by hand: segments %1.</source>
        <translation>手动添加的供血血管：血管段 %1。</translation>
    </message>
    <message>
        <source>Feeders removed by hand: segments %1.</source>
        <translation>手动移除的供血血管：血管段 %1。</translation>
    </message>
    <message>
        <source>Injection and filling</source>
        <translation>注射与充盈</translation>
    </message>
    <message>
        <source>Injected mixture</source>
        <translation>注入的混合物</translation>
    </message>
    <message>
        <source>Injected mass</source>
        <translation>注入的质量</translation>
    </message>
    <message>
        <source>Gas void fraction</source>
        <translation>气体体积分数</translation>
    </message>
    <message>
        <source>Mixture density</source>
        <translation>混合物密度</translation>
    </message>
    <message>
        <source>Mixture viscosity</source>
        <translation>混合物黏度</translation>
    </message>
    <message>
        <source>Pressure at the tip</source>
        <translation>尖端处压力</translation>
    </message>
    <message>
        <source>First outlet reached after</source>
        <translation>到达首个出口的时间</translation>
    </message>
    <message>
        <source>Last outlet reached after</source>
        <translation>到达最后一个出口的时间</translation>
    </message>
    <message>
        <source>Outlets downstream of the tip</source>
        <translation>尖端下游的出口数</translation>
    </message>
    <message>
        <source>Largest Reynolds number</source>
        <translation>最大雷诺数</translation>
    </message>
    <message>
        <source>Blood flow and the catheter (time-averaged, Newtonian blood)</source>
        <translation>血流与导管（时间平均，牛顿流体血液）</translation>
    </message>
    <message>
        <source>Arterial inflow at the tree&apos;s root</source>
        <translation>血管树根部的动脉流入量</translation>
    </message>
    <message>
        <source>Mean pressure at the root</source>
        <translation>根部平均压力</translation>
    </message>
    <message>
        <source>Vessel&apos;s own flow at the tip (catheter in, no injection)</source>
        <translation>尖端处血管自身流量（导管在位，无注射）</translation>
    </message>
    <message>
        <source>Blood reaching the tip during the injection</source>
        <translation>注射期间到达尖端的血流</translation>
    </message>
    <message>
        <source>Injected mixture in the flow below the tip (volume)</source>
        <translation>尖端下游血流中注入混合物的比例（体积）</translation>
    </message>
    <message>
        <source>Drug (liquid phase) in the flow below the tip (volume)</source>
        <translation>尖端下游血流中药物（液相）的比例（体积）</translation>
    </message>
    <message>
        <source>Catheter&apos;s share of the lumen at the tip (area)</source>
        <translation>尖端处导管占管腔的比例（面积）</translation>
    </message>
    <message>
        <source>Wedged catheter (1: yes)</source>
        <translation>导管楔入（1：是）</translation>
    </message>
    <message>
        <source>Drug refluxing past the tip</source>
        <translation>越过尖端反流的药物</translation>
    </message>
    <message>
        <source>Fixed-point iterations (fractions and viscosities)</source>
        <translation>不动点迭代次数（分数与黏度）</translation>
    </message>
    <message>
        <source>Perfusion territory and tumour coverage (TACE grading: A lesion and margin, B lesion only, C lesion partly; margin 5 mm under 25 mm, else 10 mm)</source>
        <translation>灌注区域与肿瘤覆盖（TACE 分级：A 病灶及边缘，B 仅病灶，C 部分病灶；病灶小于 25 mm 时边缘 5 mm，否则 10 mm）</translation>
    </message>
    <message>
        <source>Liver (label)</source>
        <translation>肝脏（标签）</translation>
    </message>
    <message>
        <source>Perfused territory from the tip</source>
        <translation>自尖端灌注的区域</translation>
    </message>
    <message>
        <source>Tumour in the territory</source>
        <translation>区域内的肿瘤</translation>
    </message>
    <message>
        <source>Non-tumour liver in the territory</source>
        <translation>区域内的非肿瘤肝组织</translation>
    </message>
    <message>
        <source>Coverage grade (1 A, 2 B, 3 C)</source>
        <translation>覆盖等级（1 A，2 B，3 C）</translation>
    </message>
    <message>
        <source>Lesion 1: longest diameter</source>
        <translation>病灶 1：最长径</translation>
    </message>
    <message>
        <source>Lesion 1: margin</source>
        <translation>病灶 1：边缘</translation>
    </message>
    <message>
        <source>Lesion 1: covered</source>
        <translation>病灶 1：覆盖比例</translation>
    </message>
    <message>
        <source>Lesion 1: margin covered</source>
        <translation>病灶 1：边缘覆盖比例</translation>
    </message>
    <message>
        <source>Feeders (found: entering lesion + margin, or feeding 1 % of it; with the user&apos;s edits)</source>
        <translation>供血血管（检出：进入病灶及边缘，或供应其 1 %；含用户的修改）</translation>
    </message>
    <message>
        <source>Feeders added by hand</source>
        <translation>手动添加的供血血管</translation>
    </message>
    <message>
        <source>Feeders found and removed by hand</source>
        <translation>检出后手动移除的供血血管</translation>
    </message>
    <message>
        <source>Feeders the drug from the tip reaches</source>
        <translation>药物自尖端可到达的供血血管</translation>
    </message>
    <message>
        <source>Drug to non-tumour liver</source>
        <translation>进入非肿瘤肝组织的药物</translation>
    </message>
    <message>
        <source>Drug leaving the liver (extrahepatic outlets)</source>
        <translation>离开肝脏的药物（肝外出口）</translation>
    </message>
    <message>
        <source>Best tip position&apos;s grade (1 A, 2 B, 3 C)</source>
        <translation>最佳尖端位置的等级（1 A，2 B，3 C）</translation>
    </message>
    <message>
        <source>Best tip position&apos;s non-tumour liver</source>
        <translation>最佳尖端位置的非肿瘤肝组织</translation>
    </message>
    <message>
        <source>Working C-arm angle for the path to the tip (patient supine; + LAO / - RAO, + cranial / - caudal; within LAO/RAO 60 and cranial/caudal 40 degrees)</source>
        <translation>到达尖端路径的 C 臂工作角度（患者仰卧；+ LAO / - RAO，+ 头位 / - 足位；LAO/RAO 60 度、头位/足位 40 度以内）</translation>
    </message>
    <message>
        <source>Path from node (the common hepatic artery&apos;s upper end when named, else the root)</source>
        <translation>路径起始节点（已命名时为肝总动脉上端，否则为根部）</translation>
    </message>
    <message>
        <source>LAO (+) / RAO (-)</source>
        <translation>LAO (+) / RAO (-)</translation>
    </message>
    <message>
        <source>Cranial (+) / caudal (-)</source>
        <translation>头位 (+) / 足位 (-)</translation>
    </message>
    <message>
        <source>Path foreshortened at the working angle</source>
        <translation>工作角度下路径的缩短</translation>
    </message>
    <message>
        <source>Path overlapped by other vessels at the working angle</source>
        <translation>工作角度下路径被其他血管重叠</translation>
    </message>
    <message>
        <source>Path foreshortened from the front (AP)</source>
        <translation>正位（AP）下路径的缩短</translation>
    </message>
    <message>
        <source>Path overlapped from the front (AP)</source>
        <translation>正位（AP）下路径的重叠</translation>
    </message>
    <message>
        <source>Targeting</source>
        <translation>靶向</translation>
    </message>
    <message>
        <source>Drug reaching the tumour</source>
        <translation>到达肿瘤的药物</translation>
    </message>
    <message>
        <source>Drug reaching non-target liver</source>
        <translation>到达非靶肝组织的药物</translation>
    </message>
    <message>
        <source>Outlets feeding the tumour</source>
        <translation>供应肿瘤的出口</translation>
    </message>
    <message>
        <source>Tumour share at the best tip position</source>
        <translation>最佳尖端位置的肿瘤份额</translation>
    </message>
    <message>
        <source>Candidate catheter tip positions, ranked by coverage grade, then the lesions&apos; share perfused, then the least non-tumour liver perfused</source>
        <translation>候选导管尖端位置，依次按覆盖等级、病灶灌注比例、非肿瘤肝组织灌注最少排序</translation>
    </message>
    <message>
        <source>Candidate catheter tip positions, ranked by the drug share reaching the tumour</source>
        <translation>候选导管尖端位置，按到达肿瘤的药物份额排序</translation>
    </message>
    <message>
        <source>Rank</source>
        <translation>排名</translation>
    </message>
    <message>
        <source>Node</source>
        <translation>节点</translation>
    </message>
    <message>
        <source>Position x, y, z [mm]</source>
        <translation>位置 x, y, z [mm]</translation>
    </message>
    <message>
        <source>Tumour share [%]</source>
        <translation>肿瘤份额 [%]</translation>
    </message>
    <message>
        <source>Depth [segments]</source>
        <translation>深度 [血管段]</translation>
    </message>
    <message>
        <source>Grade</source>
        <translation>等级</translation>
    </message>
    <message>
        <source>Lesions perfused [%]</source>
        <translation>病灶灌注 [%]</translation>
    </message>
    <message>
        <source>Non-tumour liver [ml]</source>
        <translation>非肿瘤肝组织 [ml]</translation>
    </message>
    <message>
        <source>Two-phase drug against a pure liquid at the control points</source>
        <translation>控制点处两相药物与纯液体的比较</translation>
    </message>
    <message>
        <source>A: drug flow, two-phase</source>
        <translation>A：药物流量，两相</translation>
    </message>
    <message>
        <source>A: drug flow, pure liquid</source>
        <translation>A：药物流量，纯液体</translation>
    </message>
    <message>
        <source>A: two-phase lower by (same injected rate)</source>
        <translation>A：两相较低的幅度（相同注射速率）</translation>
    </message>
    <message>
        <source>A: two-phase lower by (same tip pressure)</source>
        <translation>A：两相较低的幅度（相同尖端压力）</translation>
    </message>
    <message>
        <source>A: whole flow, two-phase against liquid (split shift)</source>
        <translation>A：总流量，两相与液体比较（分流偏移）</translation>
    </message>
    <message>
        <source>B: drug flow, two-phase</source>
        <translation>B：药物流量，两相</translation>
    </message>
    <message>
        <source>B: drug flow, pure liquid</source>
        <translation>B：药物流量，纯液体</translation>
    </message>
    <message>
        <source>B: two-phase lower by (same injected rate)</source>
        <translation>B：两相较低的幅度（相同注射速率）</translation>
    </message>
    <message>
        <source>B: two-phase lower by (same tip pressure)</source>
        <translation>B：两相较低的幅度（相同尖端压力）</translation>
    </message>
    <message>
        <source>B: whole flow, two-phase against liquid (split shift)</source>
        <translation>B：总流量，两相与液体比较（分流偏移）</translation>
    </message>
    <message>
        <source>The drug flow is the liquid phase&apos;s volume flow, (1 - v) c Q, with v the void fraction and c the injected mixture&apos;s share of the flow (1 when the drug flows alone); the pure liquid is the same injection with v = 0 (thesis ch. 6.4). Its drop is close to v by that definition. The split shift is the change of the whole flow: what the mixture&apos;s other viscosity does to the split.</source>
        <translation>药物流量为液相的体积流量 (1 - v) c Q，其中 v 为气体体积分数，c 为注入混合物在流量中的份额（药物单独流动时为 1）；纯液体即 v = 0 的同一注射（论文第 6.4 章）。按此定义，其下降幅度接近 v。分流偏移是总流量的变化：即混合物不同的黏度对分流的影响。</translation>
    </message>
    <message>
        <source>The tree coloured by drug flow (ml/min; grey: no drug), seen from the front</source>
        <translation>按药物流量着色的血管树（ml/min；灰色：无药物），正面观</translation>
    </message>
    <message>
        <source>drug flow [ml/min]</source>
        <translation>药物流量 [ml/min]</translation>
    </message>
    <message>
        <source>Wall mechanics: tetrahedral FEM (co-rotational linear elasticity or St. Venant-Kirchhoff), lumped mass, Rayleigh damping, backward Euler with block-Jacobi preconditioned CG (thesis ch. 4); the physiological protocol&apos;s figures from the static equilibrium after the load path.</source>
        <translation>壁力学：四面体有限元（共旋线弹性或 St. Venant-Kirchhoff），集中质量，Rayleigh 阻尼，后向欧拉法配合块 Jacobi 预条件共轭梯度（论文第 4 章）；生理方案的数值取自加载路径之后的静力平衡。</translation>
    </message>
    <message>
        <source>Blood flow: weakly compressible SPH (thesis ch. 5; Liu quartic kernel, Tait equation of state, delta-SPH density diffusion, Morris viscosity with no-slip walls whose pressure is extrapolated from the blood, leapfrog with an adaptive step) on particles seeded in the lumen label; a flow-rate inlet at the largest vessel&apos;s end and pressure outlets with particle buffers; double precision on the CPU.</source>
        <translation>血流：弱可压缩 SPH（论文第 5 章；Liu 四次核函数，Tait 状态方程，delta-SPH 密度扩散，Morris 黏性及无滑移壁面，壁面压力由血液外推，自适应步长的蛙跳积分），粒子布置于管腔标签内；最粗血管末端为流量入口，压力出口带粒子缓冲区；CPU 上双精度计算。</translation>
    </message>
    <message>
        <source>the CPU backend in double precision, explicit steps (no linear solves)</source>
        <translation>CPU 后端双精度，显式步进（无线性求解）</translation>
    </message>
    <message>
        <source>Drug delivery: two-phase homogeneous fluid in a network of conical Hagen-Poiseuille pipes, Kirchhoff solve, plug filling (thesis ch. 6).</source>
        <translation>药物输送：锥形 Hagen-Poiseuille 管网络中的两相均质流体，基尔霍夫求解，活塞式充盈（论文第 6 章）。</translation>
    </message>
    <message>
        <source>the run used the %1 backend, the cases the %2</source>
        <translation>本次运行使用 %1 后端，验证用例使用 %2</translation>
    </message>
    <message>
        <source>the run&apos;s linear solves were direct (factorised), the cases&apos; iterative (at most %1 iterations)</source>
        <translation>本次运行的线性求解为直接法（分解），验证用例为迭代法（最多 %1 次迭代）</translation>
    </message>
    <message>
        <source>the run&apos;s solves stopped at %1 iterations, the cases&apos; at %2</source>
        <translation>本次运行的求解在 %1 次迭代时停止，验证用例在 %2 次</translation>
    </message>
    <message>
        <source>the run solved to a relative residual of %1, the cases to %2 or tighter</source>
        <translation>本次运行求解至相对残差 %1，验证用例至 %2 或更严</translation>
    </message>
    <message>
        <source>The cases ran %1.</source>
        <translation>验证用例的运行方式：%1。</translation>
    </message>
    <message>
        <source>That is the configuration of the reported run.</source>
        <translation>这与所报告运行的配置一致。</translation>
    </message>
    <message>
        <source>What differs from the reported run: %1. The cases show the method, not this run&apos;s solver settings.</source>
        <translation>与所报告运行的不同之处：%1。验证用例证明的是方法，而非本次运行的求解器设置。</translation>
    </message>
    <message>
        <source>Runs: parameters, solver, validation</source>
        <translation>运行：参数、求解器、验证</translation>
    </message>
    <message>
        <source>Item</source>
        <translation>项目</translation>
    </message>
    <message>
        <source>Solver</source>
        <translation>求解器</translation>
    </message>
    <message>
        <source>Command</source>
        <translation>命令</translation>
    </message>
    <message>
        <source>Backend</source>
        <translation>后端</translation>
    </message>
    <message>
        <source>Steps</source>
        <translation>步数</translation>
    </message>
    <message>
        <source>1 (steady solve)</source>
        <translation>1（稳态求解）</translation>
    </message>
    <message>
        <source>Wall-clock time</source>
        <translation>实际耗时</translation>
    </message>
    <message>
        <source>not recorded</source>
        <translation>未记录</translation>
    </message>
    <message>
        <source>Convergence</source>
        <translation>收敛</translation>
    </message>
    <message>
        <source>Inputs</source>
        <translation>输入</translation>
    </message>
    <message>
        <source>Made</source>
        <translation>创建</translation>
    </message>
    <message>
        <source>%1 by VascuSim %2</source>
        <translation>%1，由 VascuSim %2 生成</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>警告</translation>
    </message>
    <message>
        <source>Parameters of %1</source>
        <translation>%1 的参数</translation>
    </message>
    <message>
        <source>Validation of this solver in this build (vascusim-cli validate)</source>
        <translation>此构建中该求解器的验证（vascusim-cli validate）</translation>
    </message>
    <message>
        <source>Case</source>
        <translation>用例</translation>
    </message>
    <message>
        <source>What is compared</source>
        <translation>比较内容</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>结果</translation>
    </message>
    <message>
        <source>passed</source>
        <translation>通过</translation>
    </message>
    <message>
        <source>FAILED</source>
        <translation>未通过</translation>
    </message>
    <message>
        <source>Distance along the centerline from the inlet [mm]</source>
        <translation>沿中心线距入口的距离 [mm]</translation>
    </message>
    <message>
        <source>Velocity along the centerline (cross-sections of the same run, time-averaged)</source>
        <translation>沿中心线的速度（同一运行的截面，时间平均）</translation>
    </message>
    <message>
        <source>Velocity [m/s]</source>
        <translation>速度 [m/s]</translation>
    </message>
    <message>
        <source>peak (fastest 5 % of the section)</source>
        <translation>峰值（截面中最快的 5 %）</translation>
    </message>
    <message>
        <source>mean (flow rate / area)</source>
        <translation>平均（流量 / 面积）</translation>
    </message>
    <message>
        <source>Mean pressure along the centerline (gauge; the same sections)</source>
        <translation>沿中心线的平均压力（表压；相同截面）</translation>
    </message>
    <message>
        <source>Pressure [mmHg]</source>
        <translation>压力 [mmHg]</translation>
    </message>
    <message>
        <source>section mean</source>
        <translation>截面平均</translation>
    </message>
    <message>
        <source>largest TAWSS %1 Pa</source>
        <translation>最大 TAWSS %1 Pa</translation>
    </message>
    <message>
        <source>TAWSS [Pa]</source>
        <translation>TAWSS [Pa]</translation>
    </message>
    <message>
        <source>Stenosis / blockage</source>
        <translation>狭窄 / 阻塞</translation>
    </message>
    <message>
        <source>The narrowest segment (cross-sections perpendicular to the centerline)</source>
        <translation>最窄血管段（垂直于中心线的截面）</translation>
    </message>
    <message>
        <source>Diameter stenosis</source>
        <translation>直径狭窄率</translation>
    </message>
    <message>
        <source>Area stenosis</source>
        <translation>面积狭窄率</translation>
    </message>
    <message>
        <source>Reference diameter (median)</source>
        <translation>参考直径（中位数）</translation>
    </message>
    <message>
        <source>Minimal diameter</source>
        <translation>最小直径</translation>
    </message>
    <message>
        <source>Segment length</source>
        <translation>血管段长度</translation>
    </message>
    <message>
        <source>Diameter along the narrowest segment</source>
        <translation>沿最窄血管段的直径</translation>
    </message>
    <message>
        <source>reference diameter</source>
        <translation>参考直径</translation>
    </message>
    <message>
        <source>Blockage velocity ratios and the pressure drop come from a blood-flow run (Flow &gt; Blood Flow, vascusim-cli simulate sph); the study&apos;s run has no settled flow to measure them (see its warnings).</source>
        <translation>阻塞处的速度比和压降来自血流运行（流动 &gt; 血流，vascusim-cli simulate sph）；本研究的运行没有可供测量的稳定血流（见其警告）。</translation>
    </message>
    <message>
        <source>Blockage velocity ratios and the pressure drop come from a blood-flow run (Flow &gt; Blood Flow, vascusim-cli simulate sph); this study has none.</source>
        <translation>阻塞处的速度比和压降来自血流运行（流动 &gt; 血流，vascusim-cli simulate sph）；本研究没有血流运行。</translation>
    </message>
    <message>
        <source>Blood flow (SPH run %1): the throat against the sections %2 mm upstream and downstream along the centerline, time-averaged over the settled flow; pressures gauge, the outlets at %3 mmHg</source>
        <translation>血流（SPH 运行 %1）：狭窄喉部与沿中心线上下游 %2 mm 处截面的比较，在稳定血流上时间平均；压力为表压，出口为 %3 mmHg</translation>
    </message>
    <message>
        <source>Peak velocity ratio, throat / upstream (PSV ratio&apos;s counterpart)</source>
        <translation>峰值速度比，喉部 / 上游（对应 PSV 比）</translation>
    </message>
    <message>
        <source>Peak velocity ratio, throat / downstream</source>
        <translation>峰值速度比，喉部 / 下游</translation>
    </message>
    <message>
        <source>Mean velocity ratio, throat / upstream (a mass check)</source>
        <translation>平均速度比，喉部 / 上游（质量校核）</translation>
    </message>
    <message>
        <source>Flow area ratio, upstream / throat (from the particles)</source>
        <translation>流通面积比，上游 / 喉部（由粒子计算）</translation>
    </message>
    <message>
        <source>Throat peak velocity (fastest 5 % of the section)</source>
        <translation>喉部峰值速度（截面中最快的 5 %）</translation>
    </message>
    <message>
        <source>Pressure drop, upstream - downstream (section means)</source>
        <translation>压降，上游 - 下游（截面平均）</translation>
    </message>
    <message>
        <source>Distal / proximal pressure (gauge)</source>
        <translation>远端 / 近端压力（表压）</translation>
    </message>
    <message>
        <source>Flow rate throat / upstream (1 when settled)</source>
        <translation>流量 喉部 / 上游（稳定时为 1）</translation>
    </message>
    <message>
        <source>Largest time-averaged wall shear stress (TAWSS)</source>
        <translation>最大时间平均壁面切应力（TAWSS）</translation>
    </message>
    <message>
        <source>Mean TAWSS over the surface</source>
        <translation>表面平均 TAWSS</translation>
    </message>
    <message>
        <source>Largest oscillatory shear index (0: steady)</source>
        <translation>最大振荡剪切指数（0：稳定）</translation>
    </message>
    <message>
        <source>Highest wall pressure (gauge)</source>
        <translation>最高壁面压力（表压）</translation>
    </message>
    <message>
        <source>Lowest wall pressure (gauge)</source>
        <translation>最低壁面压力（表压）</translation>
    </message>
    <message>
        <source>Time-averaged wall shear stress (TAWSS, Pa) on the lumen surface, averaged over %1-%2 ms of the same run, seen from the front; grey: no value (past an open end, or within a kernel support of it)</source>
        <translation>管腔表面的时间平均壁面切应力（TAWSS，Pa），在同一运行的 %1-%2 ms 内平均，正面观；灰色：无数值（位于开口端之外或其核函数支撑范围内）</translation>
    </message>
    <message>
        <source>These blood-flow figures come from a run that is %1.</source>
        <translation>这些血流数值来自一个状态为 %1 的运行。</translation>
    </message>
    <message>
        <source> - NOT CONVERGED</source>
        <translation> - 未收敛</translation>
    </message>
    <message>
        <source> - STOPPED EARLY</source>
        <translation> - 提前停止</translation>
    </message>
    <message>
        <source>Read these figures with care: %1.</source>
        <translation>请谨慎解读这些数值：%1。</translation>
    </message>
    <message>
        <source>Catheter tip (node, or x,y,z in mm)</source>
        <translation>导管尖端（节点，或以 mm 表示的 x,y,z）</translation>
    </message>
    <message>
        <source>Tumour sphere (x, y, z, radius; mm)</source>
        <translation>肿瘤球体（x, y, z, 半径；mm）</translation>
    </message>
    <message>
        <source>Tumour label</source>
        <translation>肿瘤标签</translation>
    </message>
    <message>
        <source>Network file</source>
        <translation>网络文件</translation>
    </message>
    <message>
        <source>Control points</source>
        <translation>控制点</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>参数</translation>
    </message>
    <message>
        <source>Distance along the centerline [mm]</source>
        <translation>沿中心线的距离 [mm]</translation>
    </message>
    <message>
        <source>Equivalent diameter [mm]</source>
        <translation>等效直径 [mm]</translation>
    </message>
    <message>
        <source>diameter</source>
        <translation>直径</translation>
    </message>
    <message>
        <source>%1: not rendered (3D snapshots need a display; run under xvfb-run).</source>
        <translation>%1：未渲染（3D 快照需要显示环境；请在 xvfb-run 下运行）。</translation>
    </message>
    <message>
        <source>%1: not rendered (%2).</source>
        <translation>%1：未渲染（%2）。</translation>
    </message>
    <message>
        <source>Perfused territory: the run had no liver label (simulate network --liver-label).</source>
        <translation>灌注区域：该运行没有肝脏标签（simulate network --liver-label）。</translation>
    </message>
    <message>
        <source>Perfused territory: the run again gave no territory.</source>
        <translation>灌注区域：重新运行未得到区域。</translation>
    </message>
    <message>
        <source>Perfused territory from the tip on the axial CT slice through the largest lesion (W 400 / L 40 HU; patient right on the left; the workstation&apos;s colours): green perfused liver, blue perfused tumour, red tumour not perfused, yellow margin not perfused, the liver not perfused unmarked (slice z = %1 mm)</source>
        <translation>自尖端灌注的区域，显示于经过最大病灶的轴位 CT 层面（W 400 / L 40 HU；患者右侧位于图像左侧；工作站配色）：绿色为灌注的肝脏，蓝色为灌注的肿瘤，红色为未灌注的肿瘤，黄色为未灌注的边缘，未灌注的肝脏不作标记（层面 z = %1 mm）</translation>
    </message>
    <message>
        <source>Perfused territory: not drawn (%1).</source>
        <translation>灌注区域：未绘制（%1）。</translation>
    </message>
    <message>
        <source>Working angle: none for this run (the tip at the root, or working_angle 0).</source>
        <translation>工作角度：本次运行没有（尖端位于根部，或 working_angle 为 0）。</translation>
    </message>
    <message>
        <source>DSA-like view at the working angle (%1, %2 deg; patient supine, the head up): the tree the contrast opacifies, the path to the tip twice as dense (%3 mm pixels)</source>
        <translation>工作角度下的类 DSA 视图（%1，%2 度；患者仰卧，头部朝上）：造影剂显影的血管树，到尖端的路径以双倍密度显示（像素 %3 mm）</translation>
    </message>
    <message>
        <source>cranial</source>
        <translation>头位</translation>
    </message>
    <message>
        <source>caudal</source>
        <translation>足位</translation>
    </message>
    <message>
        <source>Diameter along the centerline (the segment of the maximum diameter)</source>
        <translation>沿中心线的直径（最大直径所在的血管段）</translation>
    </message>
    <message>
        <source>repair threshold, men: 55 mm</source>
        <translation>修复阈值，男性：55 mm</translation>
    </message>
    <message>
        <source>repair threshold, women: 50 mm</source>
        <translation>修复阈值，女性：50 mm</translation>
    </message>
    <message>
        <source>Repair is usually considered from a maximum diameter of 5.5 cm in men and 5.0 cm in women; this one is at or above both repair thresholds.</source>
        <translation>通常在男性最大直径 5.5 cm、女性 5.0 cm 起考虑修复；此例达到或超过两个修复阈值。</translation>
    </message>
    <message>
        <source>Repair is usually considered from a maximum diameter of 5.5 cm in men and 5.0 cm in women; this one is at or above the threshold for women (5.0 cm), below the one for men (5.5 cm).</source>
        <translation>通常在男性最大直径 5.5 cm、女性 5.0 cm 起考虑修复；此例达到或超过女性阈值（5.0 cm），低于男性阈值（5.5 cm）。</translation>
    </message>
    <message>
        <source>Repair is usually considered from a maximum diameter of 5.5 cm in men and 5.0 cm in women; this one is below both repair thresholds.</source>
        <translation>通常在男性最大直径 5.5 cm、女性 5.0 cm 起考虑修复；此例低于两个修复阈值。</translation>
    </message>
    <message>
        <source>Maximum diameter, outer wall to outer wall (SVS)</source>
        <translation>最大直径，外壁至外壁（SVS）</translation>
    </message>
    <message>
        <source>Lumen diameter there (equivalent)</source>
        <translation>该处管腔直径（等效）</translation>
    </message>
    <message>
        <source>Largest thrombus thickness</source>
        <translation>最大血栓厚度</translation>
    </message>
    <message>
        <source>Sac volume</source>
        <translation>瘤囊容积</translation>
    </message>
    <message>
        <source>Sac length</source>
        <translation>瘤囊长度</translation>
    </message>
    <message>
        <source>Neck diameter (outer, at the lowest renal artery)</source>
        <translation>瘤颈直径（外径，位于最低肾动脉处）</translation>
    </message>
    <message>
        <source>Neck length</source>
        <translation>瘤颈长度</translation>
    </message>
    <message>
        <source>Neck angulation</source>
        <translation>瘤颈成角</translation>
    </message>
    <message>
        <source>Right common iliac diameter (outer)</source>
        <translation>右髂总动脉直径（外径）</translation>
    </message>
    <message>
        <source>Left common iliac diameter (outer)</source>
        <translation>左髂总动脉直径（外径）</translation>
    </message>
    <message>
        <source>Wall thickness (assumed, not measured)</source>
        <translation>壁厚（假定值，未测量）</translation>
    </message>
    <message>
        <source>The aneurysm sac (%1)</source>
        <translation>动脉瘤瘤囊（%1）</translation>
    </message>
    <message>
        <source>Definitions.</source>
        <translation>定义。</translation>
    </message>
    <message>
        <source>%1: %2.</source>
        <translation>%1：%2。</translation>
    </message>
    <message>
        <source>AAA rupture-risk review</source>
        <translation>AAA 破裂风险评估</translation>
    </message>
    <message>
        <source>The contrast lumen (cross-sections perpendicular to the centerline)</source>
        <translation>造影管腔（垂直于中心线的截面）</translation>
    </message>
    <message>
        <source>Maximum lumen diameter (equivalent)</source>
        <translation>最大管腔直径（等效）</translation>
    </message>
    <message>
        <source>Largest lumen caliper width</source>
        <translation>最大管腔卡尺宽度</translation>
    </message>
    <message>
        <source>These are lumen diameters; guidelines measure the aneurysm outer wall to outer wall with the thrombus (vascusim-cli sac). Against the lumen: %1</source>
        <translation>以上为管腔直径；指南要求测量动脉瘤外壁至外壁（含血栓）的直径（vascusim-cli sac）。按管腔计：%1</translation>
    </message>
    <message>
        <source>No centerlines and no sac: the maximum diameter was not measured.</source>
        <translation>无中心线且无瘤囊：未测量最大直径。</translation>
    </message>
    <message>
        <source>Wall stress at blood pressure (physiological protocol)</source>
        <translation>血压下的壁应力（生理方案）</translation>
    </message>
    <message>
        <source>Target blood pressure on the lumen</source>
        <translation>作用于管腔的目标血压</translation>
    </message>
    <message>
        <source>Pressure reached (the figures below are at this pressure)</source>
        <translation>达到的压力（以下数值对应此压力）</translation>
    </message>
    <message>
        <source>Peak wall stress in the sac (von Mises, 99th percentile of its elements)</source>
        <translation>瘤囊内峰值壁应力（von Mises，其单元的第 99 百分位）</translation>
    </message>
    <message>
        <source>Peak wall stress in the sac (von Mises, largest nodal value)</source>
        <translation>瘤囊内峰值壁应力（von Mises，最大节点值）</translation>
    </message>
    <message>
        <source>  its place: along the centerline below the lowest renal artery</source>
        <translation>  位置：沿中心线位于最低肾动脉以下</translation>
    </message>
    <message>
        <source>  its clock position (seen from the feet; 12 anterior, 3 patient&apos;s left)</source>
        <translation>  钟点位置（从足侧观察；12 点为前方，3 点为患者左侧）</translation>
    </message>
    <message>
        <source>Peak wall rupture index in the sac (stress / strength, 99th percentile)</source>
        <translation>瘤囊内峰值壁破裂指数（应力 / 强度，第 99 百分位）</translation>
    </message>
    <message>
        <source>Peak wall rupture index in the sac (largest nodal value)</source>
        <translation>瘤囊内峰值壁破裂指数（最大节点值）</translation>
    </message>
    <message>
        <source>  its clock position</source>
        <translation>  钟点位置</translation>
    </message>
    <message>
        <source>Highest element stress on the whole wall (von Mises; a branch ostium or the iliac crotch may set it)</source>
        <translation>整个壁面上的最高单元应力（von Mises；可能出现在分支开口或髂动脉分叉处）</translation>
    </message>
    <message>
        <source>Highest element stress on the whole wall (von Mises)</source>
        <translation>整个壁面上的最高单元应力（von Mises）</translation>
    </message>
    <message>
        <source>  at x (patient LPS)</source>
        <translation>  位于 x（患者 LPS）</translation>
    </message>
    <message>
        <source>  at y</source>
        <translation>  位于 y</translation>
    </message>
    <message>
        <source>  at z</source>
        <translation>  位于 z</translation>
    </message>
    <message>
        <source>Highest largest principal stress on the whole wall</source>
        <translation>整个壁面上的最大主应力最高值</translation>
    </message>
    <message>
        <source>Largest wall displacement</source>
        <translation>最大壁位移</translation>
    </message>
    <message>
        <source>not given</source>
        <translation>未给出</translation>
    </message>
    <message>
        <source> (the sac&apos;s neck outer diameter, or 20 mm without a sac)</source>
        <translation>（瘤颈外径，无瘤囊时为 20 mm）</translation>
    </message>
    <message>
        <source>the sac&apos;s neck outer diameter (20 mm without a sac)</source>
        <translation>瘤颈外径（无瘤囊时为 20 mm）</translation>
    </message>
    <message>
        <source>inside the sac the thrombus crossed along each element&apos;s radius from the centerline and the outer wall-to-wall chord through the centerline there (the sac&apos;s labels), elsewhere the centerline diameter and a thrombus of %1 mm</source>
        <translation>瘤囊内采用沿各单元自中心线半径方向穿过的血栓厚度及该处经中心线的外壁至外壁弦长（瘤囊标签），其他部位采用中心线直径及 %1 mm 的血栓</translation>
    </message>
    <message>
        <source>thrombus %1 mm (assumed), the centerline diameter</source>
        <translation>血栓 %1 mm（假定值），中心线直径</translation>
    </message>
    <message>
        <source>Sex and family history were not both given, so no rupture index is reported (neither is assumed).</source>
        <translation>未同时给出性别和家族史，因此不报告破裂指数（两者均不作假定）。</translation>
    </message>
    <message>
        <source>A rupture index of 1 means the stress reaches the estimated strength; it is given inside the aneurysm sac only (the regression was fitted to sacs).</source>
        <translation>破裂指数为 1 表示应力达到估计强度；仅在动脉瘤瘤囊内给出（该回归基于瘤囊拟合）。</translation>
    </message>
    <message>
        <source>No sac was measured (vascusim-cli sac), so no rupture index is given: the regression holds for the aneurysm sac only.</source>
        <translation>未测量瘤囊（vascusim-cli sac），因此不给出破裂指数：该回归仅适用于动脉瘤瘤囊。</translation>
    </message>
    <message>
        <source>Strength model: Vande Geest et al. 2006 (wall strength from the local thrombus thickness, the local diameter over the non-aneurysmal reference, family history and sex), with %1; reference diameter %2, sex %3, family history of AAA %4. %5</source>
        <translation>强度模型：Vande Geest et al. 2006（壁强度由局部血栓厚度、局部直径与非瘤段参考直径之比、家族史和性别得出），采用 %1；参考直径 %2，性别 %3，AAA 家族史 %4。%5</translation>
    </message>
    <message>
        <source>female</source>
        <translation>女</translation>
    </message>
    <message>
        <source>male</source>
        <translation>男</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>有</translation>
    </message>
    <message>
        <source>no</source>
        <translation>无</translation>
    </message>
    <message>
        <source>Wall stress (von Mises, kPa; the elements&apos; values averaged to the surface points) at blood pressure, seen from the front; PWS and PWRI mark the sac&apos;s nodal maxima (clock position seen from the feet, 12 h anterior)</source>
        <translation>血压下的壁应力（von Mises，kPa；单元值平均至表面点），正面观；PWS 和 PWRI 标记瘤囊的节点最大值（钟点位置从足侧观察，12 点为前方）</translation>
    </message>
    <message>
        <source>von Mises [kPa]</source>
        <translation>von Mises [kPa]</translation>
    </message>
    <message>
        <source>The physiological wall-stress run was not made for this study.</source>
        <translation>本研究未进行生理壁应力运行。</translation>
    </message>
    <message>
        <source>Tearing (thesis protocol: pressure ramp on the middle of the vessel)</source>
        <translation>撕裂（论文方案：作用于血管中段的压力斜坡）</translation>
    </message>
    <message>
        <source>Pressure at the first tear (-1: none)</source>
        <translation>首次撕裂时的压力（-1：无）</translation>
    </message>
    <message>
        <source>Torn elements</source>
        <translation>撕裂的单元数</translation>
    </message>
    <message>
        <source>Fracture entropy</source>
        <translation>断裂熵</translation>
    </message>
    <message>
        <source>Pressure at the end of the run</source>
        <translation>运行结束时的压力</translation>
    </message>
    <message>
        <source>Research protocol: the thesis&apos;s ramp pressures (by default 8-12 MPa, about 600 times systolic) are not physiological, and its tear strength is no measured wall strength; these figures reproduce the thesis&apos;s experiment and say nothing about this patient&apos;s rupture risk.</source>
        <translation>研究方案：论文的斜坡压力（默认 8-12 MPa，约为收缩压的 600 倍）并非生理值，其撕裂强度也不是实测的壁强度；这些数值复现论文的实验，不能说明该患者的破裂风险。</translation>
    </message>
    <message>
        <source>Tearing was quasi-static: the wall in equilibrium at each pressure, the onset bracketed by bisection to 0.5 %, one element released per equilibrium.</source>
        <translation>撕裂为准静态：每个压力下壁处于平衡，撕裂起点以二分法界定至 0.5 %，每次平衡释放一个单元。</translation>
    </message>
    <message>
        <source>Tearing followed the thesis&apos;s damped ramp: the wall lags the load, so the onset pressure depends on the ramp&apos;s rate.</source>
        <translation>撕裂遵循论文的阻尼斜坡：壁的响应滞后于载荷，因此起始压力取决于斜坡速率。</translation>
    </message>
    <message>
        <source>The thesis tearing protocol was not run for this study.</source>
        <translation>本研究未运行论文的撕裂方案。</translation>
    </message>
    <message>
        <source>VascuSim planning report</source>
        <translation>VascuSim 规划报告</translation>
    </message>
    <message>
        <source>AAA rupture-risk review: the study has no AAA sac (vascusim-cli sac) and no wall-mechanics run (simulate fem).</source>
        <translation>AAA 破裂风险评估：本研究没有 AAA 瘤囊（vascusim-cli sac），也没有壁力学运行（simulate fem）。</translation>
    </message>
    <message>
        <source>Stenosis / blockage: no segment of the centerlines narrows by 40 % or more, and the study has no blood-flow run (velocity ratios, pressure drop).</source>
        <translation>狭窄 / 阻塞：中心线上没有狭窄 40 % 及以上的血管段，本研究也没有血流运行（速度比、压降）。</translation>
    </message>
    <message>
        <source>Chemoembolization: the study has no drug-delivery run (simulate network).</source>
        <translation>化疗栓塞：本研究没有药物输送运行（simulate network）。</translation>
    </message>
    <message>
        <source> (posterior)</source>
        <translation>（后方）</translation>
    </message>
    <message>
        <source>Surgical smoke: stable fluids on a MAC grid (thesis ch. 7; semi-Lagrangian velocity advection, conservative limited transport of the smoke, Boussinesq buoyancy, vorticity confinement and vortex particles), the pressure projection by multigrid-preconditioned conjugate gradients; single precision on the CPU.</source>
        <translation>手术烟雾：MAC 网格上的稳定流体方法（论文第 7 章；速度的半拉格朗日平流、烟雾的守恒限制输运、Boussinesq 浮力、涡量约束与涡粒子），压力投影采用多重网格预条件共轭梯度；CPU 上单精度计算。</translation>
    </message>
    <message>
        <source>Endoscopic vessel harvesting: a CO2 tunnel drawn around 60 mm of the study&apos;s longest centerline segment (a pre-operative CT shows no tunnel), the cautery&apos;s contact on the vessel&apos;s anterior wall, smoke from 9 s after contact (thesis ch. 7), the endoscope 25 mm back in the tunnel.</source>
        <translation>内镜血管采集：围绕本研究最长中心线血管段 60 mm 绘制的 CO2 隧道（术前 CT 不显示隧道），电刀接触血管前壁，接触后 9 s 起产生烟雾（论文第 7 章），内镜位于隧道内后方 25 mm 处。</translation>
    </message>
    <message>
        <source>Liver ablation under laparoscopy: an insufflated dome over the liver (the study&apos;s liver label, or a box phantom without one), the probe&apos;s smoke at the liver&apos;s surface, the insufflator a vent in the roof, a suction port beside the probe, the laparoscope looking down at the site.</source>
        <translation>腹腔镜下肝消融：肝脏上方的充气穹顶（本研究的肝脏标签，无标签时为长方体体模），探头在肝脏表面产生烟雾，气腹机为顶部的通气口，探头旁设抽吸口，腹腔镜自上方观察该处。</translation>
    </message>
    <message>
        <source>The thesis demo: a 1 m box open at the top, smoke rising from the floor, a ball dropped through it.</source>
        <translation>论文演示：顶部开口的 1 m 箱体，烟雾自底部升起，一个球从中落下。</translation>
    </message>
    <message>
        <source>Surgical smoke (illustrative scene)</source>
        <translation>手术烟雾（示意场景）</translation>
    </message>
    <message>
        <source>The scene is illustrative: its geometry is synthetic and the smoke&apos;s emission is an assumption; the figures show how the smoke spreads and clears, not this patient&apos;s case.</source>
        <translation>该场景仅为示意：其几何为合成，烟雾排放量为假定值；这些数值显示烟雾如何扩散和消散，而非该患者的具体情况。</translation>
    </message>
    <message>
        <source>The endoscope&apos;s view</source>
        <translation>内镜视野</translation>
    </message>
    <message>
        <source>Time to 50 % of the view obscured</source>
        <translation>视野 50 % 被遮挡的时间</translation>
    </message>
    <message>
        <source>Time to 90 % of the view obscured</source>
        <translation>视野 90 % 被遮挡的时间</translation>
    </message>
    <message>
        <source>Largest share of the view obscured</source>
        <translation>视野被遮挡的最大比例</translation>
    </message>
    <message>
        <source>Share of the view obscured at the end</source>
        <translation>结束时视野被遮挡的比例</translation>
    </message>
    <message>
        <source>Smoke in the cavity at the end</source>
        <translation>结束时腔内的烟雾量</translation>
    </message>
    <message>
        <source>Time to clear after the suction starts (under 10 % obscured)</source>
        <translation>抽吸开始后视野恢复清晰的时间（遮挡低于 10 %）</translation>
    </message>
    <message>
        <source>Smoke removed in the suction&apos;s first 10 s</source>
        <translation>抽吸最初 10 s 内清除的烟雾</translation>
    </message>
    <message>
        <source>A pixel of the endoscope&apos;s view is obscured when less than %1 % of the light from the scene passes the smoke (Beer-Lambert, the mass extinction coefficient %2 m^2/g: Mulholland &amp; Croarkin 2000).</source>
        <translation>当来自场景的光穿过烟雾的比例低于 %1 % 时，内镜视野中的像素视为被遮挡（Beer-Lambert，质量消光系数 %2 m^2/g：Mulholland &amp; Croarkin 2000）。</translation>
    </message>
    <message>
        <source>Not reached within the run: %1.</source>
        <translation>运行期间未达到：%1。</translation>
    </message>
    <message>
        <source>The suction&apos;s flow is calibrated to a published measurement (proximal evacuation removing about 85 % of the smoke in 10 s, Chou 2024): a calibration, not a validation.</source>
        <translation>抽吸流量依据已发表的测量进行校准（近端排烟在 10 s 内清除约 85 % 的烟雾，Chou 2024）：这是校准而非验证。</translation>
    </message>
    <message>
        <source>The endoscope&apos;s view obscured by the smoke over time</source>
        <translation>内镜视野随时间被烟雾遮挡的情况</translation>
    </message>
    <message>
        <source>Time [s]</source>
        <translation>时间 [s]</translation>
    </message>
    <message>
        <source>View obscured [%]</source>
        <translation>视野遮挡 [%]</translation>
    </message>
    <message>
        <source>obscured</source>
        <translation>遮挡</translation>
    </message>
    <message>
        <source>50 %</source>
        <translation>50 %</translation>
    </message>
    <message>
        <source>90 %</source>
        <translation>90 %</translation>
    </message>
    <message>
        <source>Surgical smoke: the study has no smoke run (simulate smoke).</source>
        <translation>手术烟雾：本研究没有烟雾运行（simulate smoke）。</translation>
    </message>
    <message>
        <source>Scenario</source>
        <translation>场景</translation>
    </message>
    <message>
        <source>Wall loads on the lumen surface (the same run and window; tau_w: the walls&apos; friction on the particles next to them)</source>
        <translation>管腔表面的壁面载荷（同一运行与时间窗；tau_w：壁面对近壁粒子的摩擦力）</translation>
    </message>
    <message>
        <source>n/a</source>
        <translation>不适用</translation>
    </message>
    <message>
        <source>Wall mechanics: quadratic (10-node) tetrahedral FEM, the Raghavan &amp; Vorp 2000 hyperelastic AAA wall (nearly incompressible), the blood pressure as a follower load on the lumen, ends held; the static equilibrium by Newton&apos;s method (GMRES preconditioned by a sparse Cholesky or LU factorisation) to the force tolerance. The imaged geometry is taken as unloaded (CT shows the vessel at its pressure); the intraluminal thrombus, where the wall mesh has it, as its own layer (Wang et al. 2001).</source>
        <translation>管壁力学：二次（10 节点）四面体有限元，Raghavan &amp; Vorp 2000 超弹性 AAA 管壁（近乎不可压缩），血压作为随动载荷作用于管腔，两端固定；以牛顿法求解静力平衡（GMRES，以稀疏 Cholesky 或 LU 分解作预条件）直至力容差。成像几何被视为无载状态（CT 显示的是血管在其压力下的形态）；腔内血栓（若管壁网格包含）作为独立一层（Wang 等 2001）。</translation>
    </message>
</context>
<context>
    <name>vsim::Error</name>
    <message>
        <source>the series belongs to another patient than the study (Patient ID differs); import it into a study of its own</source>
        <translation>该序列属于与本研究不同的患者（患者 ID 不同）；请将其导入单独的研究</translation>
    </message>
    <message>
        <source>the needle&apos;s bore, the generation rate and the box&apos;s depth must be positive, the box&apos;s margin not negative</source>
        <translation>针孔、生成速率和盒子深度必须为正，盒子边距不得为负</translation>
    </message>
    <message>
        <source>cannot write the run file</source>
        <translation>无法写入运行文件</translation>
    </message>
    <message>
        <source>file</source>
        <translation>文件</translation>
    </message>
    <message>
        <source>the drug run records no centerlines to run again from</source>
        <translation>该药物运行未记录可重新运行所用的中心线</translation>
    </message>
    <message>
        <source>artifact</source>
        <translation>工件</translation>
    </message>
    <message>
        <source>cannot create the run folder</source>
        <translation>无法创建运行文件夹</translation>
    </message>
    <message>
        <source>folder</source>
        <translation>文件夹</translation>
    </message>
    <message>
        <source>cannot write metrics.json</source>
        <translation>无法写入 metrics.json</translation>
    </message>
    <message>
        <source>the wall-load surface has no TAWSS</source>
        <translation>壁面载荷表面没有 TAWSS</translation>
    </message>
    <message>
        <source>no vertex of the wall-load surface was sampled</source>
        <translation>壁面载荷表面的顶点均未被采样</translation>
    </message>
    <message>
        <source>not a centerlines artifact</source>
        <translation>不是中心线工件</translation>
    </message>
    <message>
        <source>segment</source>
        <translation>节段</translation>
    </message>
    <message>
        <source>a segment&apos;s name cannot be empty</source>
        <translation>节段名称不能为空</translation>
    </message>
    <message>
        <source>the evh scenario places its tunnel around a vessel: the study has no centerlines (vascusim-cli centerlines)</source>
        <translation>EVH 场景将隧道置于血管周围：该研究没有中心线（vascusim-cli centerlines）</translation>
    </message>
    <message>
        <source>the study&apos;s centerlines have no segment for the evh tunnel</source>
        <translation>该研究的中心线中没有可用于 EVH 隧道的节段</translation>
    </message>
    <message>
        <source>not a translation catalogue (.qm)</source>
        <translation>不是翻译目录（.qm）</translation>
    </message>
    <message>
        <source>a sheet needs a positive size, a cell size and at least 0.05 mm thickness</source>
        <translation>薄层需要正的尺寸、单元尺寸和至少 0.05 mm 的厚度</translation>
    </message>
    <message>
        <source>scaledSum: x and y differ in length</source>
        <translation>scaledSum：x 与 y 长度不同</translation>
    </message>
    <message>
        <source>no CUDA device: run the wall solver on the CPU (--backend cpu)</source>
        <translation>没有 CUDA 设备：请在 CPU 上运行管壁求解器（--backend cpu）</translation>
    </message>
    <message>
        <source>the CUDA backend runs the co-rotational linear model only: run St. Venant-Kirchhoff on the CPU (--backend cpu)</source>
        <translation>CUDA 后端仅支持共旋线性模型：St. Venant-Kirchhoff 模型请在 CPU 上运行（--backend cpu）</translation>
    </message>
    <message>
        <source>the smoke&apos;s CUDA backend needs a CUDA device, and there is none</source>
        <translation>烟雾的 CUDA 后端需要 CUDA 设备，但没有找到</translation>
    </message>
    <message>
        <source>the smoke&apos;s CUDA backend takes grids of fewer than 2^31 cells</source>
        <translation>烟雾的 CUDA 后端只接受少于 2^31 个单元的网格</translation>
    </message>
    <message>
        <source>the smoke&apos;s CUDA backend was made for another grid</source>
        <translation>烟雾的 CUDA 后端是为另一网格创建的</translation>
    </message>
    <message>
        <source>no CUDA device: run the SPH solver on the CPU (--backend cpu)</source>
        <translation>没有 CUDA 设备：请在 CPU 上运行 SPH 求解器（--backend cpu）</translation>
    </message>
    <message>
        <source>the CUDA SPH backend runs no periodic axes or tracer absorption yet: run this case on the CPU (--backend cpu)</source>
        <translation>CUDA SPH 后端尚不支持周期轴或示踪剂吸收：请在 CPU 上运行此算例（--backend cpu）</translation>
    </message>
    <message>
        <source>cancelled by the user</source>
        <translation>已被用户取消</translation>
    </message>
    <message>
        <source>image volume adopted an empty buffer</source>
        <translation>图像体积接收了空缓冲区</translation>
    </message>
    <message>
        <source>--rescale needs a finite, non-zero slope and a finite intercept</source>
        <translation>--rescale 需要有限且非零的斜率和有限的截距</translation>
    </message>
    <message>
        <source>option</source>
        <translation>选项</translation>
    </message>
    <message>
        <source>cannot write into the output folder</source>
        <translation>无法写入输出文件夹</translation>
    </message>
    <message>
        <source>the output path is a file, not a folder; VascuSim does not replace it</source>
        <translation>输出路径是文件而不是文件夹；VascuSim 不会替换它</translation>
    </message>
    <message>
        <source>path</source>
        <translation>路径</translation>
    </message>
    <message>
        <source>the output folder holds files VascuSim did not write; choose a new or empty folder</source>
        <translation>输出文件夹包含非 VascuSim 写入的文件；请选择新的或空的文件夹</translation>
    </message>
    <message>
        <source>the output path is a folder; VascuSim writes a file there only where nothing is</source>
        <translation>输出路径是文件夹；VascuSim 只在空位置写入文件</translation>
    </message>
    <message>
        <source>the output file exists; give --overwrite to replace it</source>
        <translation>输出文件已存在；如需替换请使用 --overwrite</translation>
    </message>
    <message>
        <source>the output path is not a regular file; VascuSim does not replace it</source>
        <translation>输出路径不是普通文件；VascuSim 不会替换它</translation>
    </message>
    <message>
        <source>parameter declared twice</source>
        <translation>参数重复声明</translation>
    </message>
    <message>
        <source>key</source>
        <translation>键</translation>
    </message>
    <message>
        <source>parameter default outside its declared range</source>
        <translation>参数默认值超出其声明范围</translation>
    </message>
    <message>
        <source>default</source>
        <translation>默认值</translation>
    </message>
    <message>
        <source>range</source>
        <translation>范围</translation>
    </message>
    <message>
        <source>known parameters</source>
        <translation>已知参数</translation>
    </message>
    <message>
        <source>text</source>
        <translation>文本</translation>
    </message>
    <message>
        <source>value</source>
        <translation>值</translation>
    </message>
    <message>
        <source>the principal axis of no points</source>
        <translation>零个点的主轴</translation>
    </message>
    <message>
        <source>skeleton edge refers to a missing node</source>
        <translation>骨架边引用了不存在的节点</translation>
    </message>
    <message>
        <source>skeleton edge has fewer than two points</source>
        <translation>骨架边少于两个点</translation>
    </message>
    <message>
        <source>skeleton edge has point, voxel and radius lists of different lengths</source>
        <translation>骨架边的点、体素和半径列表长度不同</translation>
    </message>
    <message>
        <source>skeleton edge has a radius that is not positive</source>
        <translation>骨架边存在非正半径</translation>
    </message>
    <message>
        <source>tetrahedron refers to a missing point</source>
        <translation>四面体引用了不存在的点</translation>
    </message>
    <message>
        <source>element</source>
        <translation>单元</translation>
    </message>
    <message>
        <source>point</source>
        <translation>点</translation>
    </message>
    <message>
        <source>inverted or degenerate tetrahedron</source>
        <translation>四面体翻转或退化</translation>
    </message>
    <message>
        <source>point field length differs from the point count</source>
        <translation>点场长度与点数不一致</translation>
    </message>
    <message>
        <source>field</source>
        <translation>场</translation>
    </message>
    <message>
        <source>cell field length differs from the element count</source>
        <translation>单元场长度与单元数不一致</translation>
    </message>
    <message>
        <source>triangle refers to a missing point</source>
        <translation>三角形引用了不存在的点</translation>
    </message>
    <message>
        <source>triangle</source>
        <translation>三角形</translation>
    </message>
    <message>
        <source>triangle repeats a point</source>
        <translation>三角形含有重复的点</translation>
    </message>
    <message>
        <source>node</source>
        <translation>节点</translation>
    </message>
    <message>
        <source>an ROI takes two corner points</source>
        <translation>ROI 需要两个角点</translation>
    </message>
    <message>
        <source>volume dimension is not positive</source>
        <translation>体积尺寸不为正</translation>
    </message>
    <message>
        <source>axis</source>
        <translation>轴</translation>
    </message>
    <message>
        <source>size</source>
        <translation>大小</translation>
    </message>
    <message>
        <source>voxel spacing must be positive and finite (mm)</source>
        <translation>体素间距必须为正且有限（mm）</translation>
    </message>
    <message>
        <source>spacing</source>
        <translation>间距</translation>
    </message>
    <message>
        <source>volume origin is not finite</source>
        <translation>体积原点不是有限值</translation>
    </message>
    <message>
        <source>direction matrix is not orthonormal</source>
        <translation>方向矩阵不是正交归一的</translation>
    </message>
    <message>
        <source>deviation</source>
        <translation>偏差</translation>
    </message>
    <message>
        <source>the AAA phantom&apos;s aneurysm is smaller than 1.5 times its neck; choose a larger --max-diameter</source>
        <translation>AAA 体模的动脉瘤小于其瘤颈的 1.5 倍；请选择更大的 --max-diameter</translation>
    </message>
    <message>
        <source>unknown transfer syntax</source>
        <translation>未知的传输语法</translation>
    </message>
    <message>
        <source>cannot set a DICOM attribute</source>
        <translation>无法设置 DICOM 属性</translation>
    </message>
    <message>
        <source>tag</source>
        <translation>标签</translation>
    </message>
    <message>
        <source>reason</source>
        <translation>原因</translation>
    </message>
    <message>
        <source>cannot create a DICOM sequence item</source>
        <translation>无法创建 DICOM 序列项</translation>
    </message>
    <message>
        <source>HU value outside -1024..3071 cannot be stored in 12 unsigned bits</source>
        <translation>-1024..3071 以外的 HU 值无法以 12 位无符号数存储</translation>
    </message>
    <message>
        <source>cannot encode the pixel data</source>
        <translation>无法编码像素数据</translation>
    </message>
    <message>
        <source>cannot write DICOM file</source>
        <translation>无法写入 DICOM 文件</translation>
    </message>
    <message>
        <source>the pixels and the slice stack of a CT series disagree</source>
        <translation>CT 序列的像素与层面堆栈不一致</translation>
    </message>
    <message>
        <source>file name prefix must have at most 2 characters (8-character DICOMDIR names)</source>
        <translation>文件名前缀最多 2 个字符（DICOMDIR 名称为 8 个字符）</translation>
    </message>
    <message>
        <source>cannot create the output folder</source>
        <translation>无法创建输出文件夹</translation>
    </message>
    <message>
        <source>DICOM image has no rows or columns</source>
        <translation>DICOM 图像没有行或列</translation>
    </message>
    <message>
        <source>inconsistent Bits Stored / High Bit</source>
        <translation>Bits Stored / High Bit 不一致</translation>
    </message>
    <message>
        <source>frame index out of range</source>
        <translation>帧索引超出范围</translation>
    </message>
    <message>
        <source>frame</source>
        <translation>帧</translation>
    </message>
    <message>
        <source>pixel data is shorter than the image it describes (truncated file?)</source>
        <translation>像素数据短于其描述的图像（文件被截断？）</translation>
    </message>
    <message>
        <source>JPEG 2000 code stream size differs from the image&apos;s rows and columns</source>
        <translation>JPEG 2000 码流尺寸与图像行列数不符</translation>
    </message>
    <message>
        <source>JPEG 2000 pixel data has no code stream header</source>
        <translation>JPEG 2000 像素数据没有码流头</translation>
    </message>
    <message>
        <source>compressed pixel data has no fragments</source>
        <translation>压缩像素数据没有片段</translation>
    </message>
    <message>
        <source>compressed pixel data fragment unreadable</source>
        <translation>压缩像素数据片段无法读取</translation>
    </message>
    <message>
        <source>multi-frame JPEG 2000 with several fragments per frame is not supported</source>
        <translation>不支持每帧多个片段的多帧 JPEG 2000</translation>
    </message>
    <message>
        <source>damaged JPEG stream: no start of image</source>
        <translation>JPEG 数据流损坏：缺少图像起始标记</translation>
    </message>
    <message>
        <source>damaged JPEG stream: marker expected</source>
        <translation>JPEG 数据流损坏：此处应为标记</translation>
    </message>
    <message>
        <source>damaged JPEG stream: ends in fill bytes</source>
        <translation>JPEG 数据流损坏：以填充字节结束</translation>
    </message>
    <message>
        <source>damaged JPEG stream: unexpected marker before the scan</source>
        <translation>JPEG 数据流损坏：扫描前出现意外标记</translation>
    </message>
    <message>
        <source>damaged JPEG stream: truncated marker segment</source>
        <translation>JPEG 数据流损坏：标记段被截断</translation>
    </message>
    <message>
        <source>damaged JPEG stream: bad marker segment length</source>
        <translation>JPEG 数据流损坏：标记段长度错误</translation>
    </message>
    <message>
        <source>damaged JPEG stream: scan without a frame header</source>
        <translation>JPEG 数据流损坏：扫描缺少帧头</translation>
    </message>
    <message>
        <source>cannot decode the JPEG 2000 code stream</source>
        <translation>无法解码 JPEG 2000 码流</translation>
    </message>
    <message>
        <source>cannot decompress the pixel data</source>
        <translation>无法解压缩像素数据</translation>
    </message>
    <message>
        <source>transfer_syntax</source>
        <translation>传输语法</translation>
    </message>
    <message>
        <source>pixel data missing</source>
        <translation>缺少像素数据</translation>
    </message>
    <message>
        <source>pixel data longer than the file (damaged length or truncated file)</source>
        <translation>像素数据长于文件（长度损坏或文件被截断）</translation>
    </message>
    <message>
        <source>cannot read the pixel data</source>
        <translation>无法读取像素数据</translation>
    </message>
    <message>
        <source>cannot open the file</source>
        <translation>无法打开文件</translation>
    </message>
    <message>
        <source>not a greyscale image</source>
        <translation>不是灰度图像</translation>
    </message>
    <message>
        <source>photometric</source>
        <translation>光度解释</translation>
    </message>
    <message>
        <source>damaged or truncated DICOM file</source>
        <translation>DICOM 文件损坏或被截断</translation>
    </message>
    <message>
        <source>decodeFramesToHu: one output per frame expected</source>
        <translation>decodeFramesToHu：每帧应有一个输出</translation>
    </message>
    <message>
        <source>needed_bytes</source>
        <translation>所需字节数</translation>
    </message>
    <message>
        <source>available_bytes</source>
        <translation>可用字节数</translation>
    </message>
    <message>
        <source>cannot read the DICOMDIR</source>
        <translation>无法读取 DICOMDIR</translation>
    </message>
    <message>
        <source>the DICOMDIR has no directory records</source>
        <translation>DICOMDIR 没有目录记录</translation>
    </message>
    <message>
        <source>no such file or folder</source>
        <translation>没有此文件或文件夹</translation>
    </message>
    <message>
        <source>the DICOM SEG&apos;s per-frame functional groups do not match its number of frames</source>
        <translation>DICOM SEG 的逐帧功能组与其帧数不符</translation>
    </message>
    <message>
        <source>the DICOM SEG&apos;s frames have several orientations: not one volume</source>
        <translation>DICOM SEG 的帧具有多个方向：不是单一体积</translation>
    </message>
    <message>
        <source>the DICOM SEG&apos;s frames are shifted within their planes: not one volume</source>
        <translation>DICOM SEG 的帧在平面内存在偏移：不是单一体积</translation>
    </message>
    <message>
        <source>the DICOM SEG has no readable pixel data (compressed SEG objects are not supported)</source>
        <translation>DICOM SEG 没有可读的像素数据（不支持压缩的 SEG 对象）</translation>
    </message>
    <message>
        <source>the label cannot be written as a DICOM SEG (empty, or over 65535 pixels a row)</source>
        <translation>标签无法写为 DICOM SEG（为空，或每行超过 65535 像素）</translation>
    </message>
    <message>
        <source>the label has no labelled voxel to write as a DICOM SEG</source>
        <translation>标签中没有可写为 DICOM SEG 的已标记体素</translation>
    </message>
    <message>
        <source>writing the DICOM SEG failed at the referenced series</source>
        <translation>写入 DICOM SEG 时在引用序列处失败</translation>
    </message>
    <message>
        <source>a retrieve needs the study&apos;s instance UID</source>
        <translation>检索需要研究的实例 UID</translation>
    </message>
    <message>
        <source>a series query needs the study&apos;s instance UID</source>
        <translation>序列查询需要研究的实例 UID</translation>
    </message>
    <message>
        <source>nothing to store: name one or more DICOM files</source>
        <translation>没有可存储的内容：请指定一个或多个 DICOM 文件</translation>
    </message>
    <message>
        <source>phantom size must be 8..4096 voxels per axis</source>
        <translation>体模尺寸必须为每轴 8..4096 个体素</translation>
    </message>
    <message>
        <source>phantom spacing must be 0.05..20 mm</source>
        <translation>体模间距必须为 0.05..20 mm</translation>
    </message>
    <message>
        <source>phantom noise must be 0..500 HU</source>
        <translation>体模噪声必须为 0..500 HU</translation>
    </message>
    <message>
        <source>phantom blur must be at most 10 mm</source>
        <translation>体模模糊最大为 10 mm</translation>
    </message>
    <message>
        <source>aneurysm diameter must be 20..120 mm</source>
        <translation>动脉瘤直径必须为 20..120 mm</translation>
    </message>
    <message>
        <source>phantom PSF FWHM must be 0.1..5 mm</source>
        <translation>体模 PSF 半高宽必须为 0.1..5 mm</translation>
    </message>
    <message>
        <source>stenosis must be 0..95 percent</source>
        <translation>狭窄必须为 0..95%</translation>
    </message>
    <message>
        <source>the second stenosis must be 0..95 percent</source>
        <translation>第二处狭窄必须为 0..95%</translation>
    </message>
    <message>
        <source>the vessel diameter must be 1..40 mm</source>
        <translation>血管直径必须为 1..40 mm</translation>
    </message>
    <message>
        <source>the stenosis length must be 2..100 mm (0: drawn from the seed)</source>
        <translation>狭窄长度必须为 2..100 mm（0：由随机种子决定）</translation>
    </message>
    <message>
        <source>cannot write truth.json</source>
        <translation>无法写入 truth.json</translation>
    </message>
    <message>
        <source>the series has images without Image Position/Orientation (Patient): it cannot be placed in the patient frame</source>
        <translation>该序列有图像缺少 Image Position/Orientation (Patient)：无法置于患者坐标系中</translation>
    </message>
    <message>
        <source>the series has images without Pixel Spacing</source>
        <translation>该序列有图像缺少 Pixel Spacing</translation>
    </message>
    <message>
        <source>the series has no images</source>
        <translation>该序列没有图像</translation>
    </message>
    <message>
        <source>the lumen label is not on the CT&apos;s grid</source>
        <translation>管腔标签不在 CT 的网格上</translation>
    </message>
    <message>
        <source>the wall thickness must be 0..5 mm</source>
        <translation>管壁厚度必须为 0..5 mm</translation>
    </message>
    <message>
        <source>no abdominal aorta found (a round contrast-filled cross-section in front of the spine in three neighbouring slices): give a point inside it with --seed x,y,z</source>
        <translation>未找到腹主动脉（在三个相邻层面中脊柱前方的圆形造影剂充盈截面）：请用 --seed x,y,z 指定其中一点</translation>
    </message>
    <message>
        <source>the label holds no aorta-sized cross-section (50 mm2 or more): segment the aorta first (vascusim-cli segment --target aorta)</source>
        <translation>标签中没有主动脉大小的截面（50 mm2 或以上）：请先分割主动脉（vascusim-cli segment --target aorta）</translation>
    </message>
    <message>
        <source>the skeleton is empty: run the skeleton step first</source>
        <translation>骨架为空：请先运行骨架步骤</translation>
    </message>
    <message>
        <source>the centerline step must be positive</source>
        <translation>中心线步长必须为正</translation>
    </message>
    <message>
        <source>the guided segmentation needs at least one include point inside the vessel</source>
        <translation>引导分割至少需要一个位于血管内的包含点</translation>
    </message>
    <message>
        <source>at most 250 include and exclude points</source>
        <translation>包含点和排除点最多 250 个</translation>
    </message>
    <message>
        <source>the points grew no vessel: pick them inside the contrast-filled lumen</source>
        <translation>这些点未生长出血管：请将它们放在造影剂充盈的管腔内</translation>
    </message>
    <message>
        <source>cannot merge a paint and an erase stroke</source>
        <translation>无法合并绘制笔划和擦除笔划</translation>
    </message>
    <message>
        <source>there is no label to edit</source>
        <translation>没有可编辑的标签</translation>
    </message>
    <message>
        <source>the brush needs a positive radius</source>
        <translation>画笔需要正的半径</translation>
    </message>
    <message>
        <source>the brush needs a plane</source>
        <translation>画笔需要一个平面</translation>
    </message>
    <message>
        <source>the label is empty: segment the vessels first</source>
        <translation>标签为空：请先分割血管</translation>
    </message>
    <message>
        <source>the liver label holds no voxel near the points</source>
        <translation>肝脏标签在这些点附近没有体素</translation>
    </message>
    <message>
        <source>place at least one point inside the lesion</source>
        <translation>请在病灶内至少放置一个点</translation>
    </message>
    <message>
        <source>a point lies outside the CT</source>
        <translation>有一个点位于 CT 之外</translation>
    </message>
    <message>
        <source>point_mm</source>
        <translation>点（mm）</translation>
    </message>
    <message>
        <source>a point lies outside the liver label: place the points inside the lesion, in the liver</source>
        <translation>有一个点位于肝脏标签之外：请将点放在肝内的病灶中</translation>
    </message>
    <message>
        <source>level set: the mask and the contrast image differ in size</source>
        <translation>水平集：掩模与造影图像大小不同</translation>
    </message>
    <message>
        <source>place at least one point inside the organ</source>
        <translation>请在器官内至少放置一个点</translation>
    </message>
    <message>
        <source>the points&apos; intensity window holds nothing: place them inside the organ</source>
        <translation>这些点的强度窗内没有任何体素：请将它们放在器官内</translation>
    </message>
    <message>
        <source>no centerlines to measure</source>
        <translation>没有可测量的中心线</translation>
    </message>
    <message>
        <source>no centerlines to measure: run vascusim-cli centerline first</source>
        <translation>没有可测量的中心线：请先运行 vascusim-cli centerline</translation>
    </message>
    <message>
        <source>no CT image to segment</source>
        <translation>没有可分割的 CT 图像</translation>
    </message>
    <message>
        <source>min_contrast_hu must be below max_contrast_hu</source>
        <translation>min_contrast_hu 必须小于 max_contrast_hu</translation>
    </message>
    <message>
        <source>the segmentation is empty: try a seed inside a vessel or a lower min_contrast_hu</source>
        <translation>分割结果为空：请尝试将种子点放在血管内或降低 min_contrast_hu</translation>
    </message>
    <message>
        <source>Dice needs two labels on the same grid</source>
        <translation>Dice 需要同一网格上的两个标签</translation>
    </message>
    <message>
        <source>the ROI holds no voxel of the image: draw it larger or inside the volume</source>
        <translation>ROI 中没有图像体素：请画大一些或画在体积内</translation>
    </message>
    <message>
        <source>an angle&apos;s arms must have a length: its points coincide</source>
        <translation>角的边必须有长度：其点重合</translation>
    </message>
    <message>
        <source>ITK image is not fully buffered from index 0; cannot adopt it</source>
        <translation>ITK 图像未从索引 0 完整缓冲；无法接收</translation>
    </message>
    <message>
        <source>cannot write NRRD image</source>
        <translation>无法写入 NRRD 图像</translation>
    </message>
    <message>
        <source>cannot read NRRD image</source>
        <translation>无法读取 NRRD 图像</translation>
    </message>
    <message>
        <source>cannot read NRRD header</source>
        <translation>无法读取 NRRD 头</translation>
    </message>
    <message>
        <source>image file is not 3D</source>
        <translation>图像文件不是三维的</translation>
    </message>
    <message>
        <source>VTK image has no scalars</source>
        <translation>VTK 图像没有标量</translation>
    </message>
    <message>
        <source>VTK image scalars are not single-component of the expected type</source>
        <translation>VTK 图像标量不是预期类型的单分量数据</translation>
    </message>
    <message>
        <source>vtk type</source>
        <translation>VTK 类型</translation>
    </message>
    <message>
        <source>no surface to convert</source>
        <translation>没有可转换的表面</translation>
    </message>
    <message>
        <source>surface polygon is not a triangle</source>
        <translation>表面多边形不是三角形</translation>
    </message>
    <message>
        <source>points</source>
        <translation>点数</translation>
    </message>
    <message>
        <source>no tetrahedral mesh to convert</source>
        <translation>没有可转换的四面体网格</translation>
    </message>
    <message>
        <source>mesh cell is not a linear tetrahedron</source>
        <translation>网格单元不是线性四面体</translation>
    </message>
    <message>
        <source>cell</source>
        <translation>单元</translation>
    </message>
    <message>
        <source>vtk cell type</source>
        <translation>VTK 单元类型</translation>
    </message>
    <message>
        <source>no vessel network to convert</source>
        <translation>没有可转换的血管网络</translation>
    </message>
    <message>
        <source>not a vessel network frame: a line does not run from node to node</source>
        <translation>不是血管网络帧：有一条线不是连接节点到节点</translation>
    </message>
    <message>
        <source>line</source>
        <translation>线</translation>
    </message>
    <message>
        <source>a grid field does not match its grid</source>
        <translation>网格场与其网格不匹配</translation>
    </message>
    <message>
        <source>not a voxel-grid frame: no point arrays</source>
        <translation>不是体素网格帧：没有点数组</translation>
    </message>
    <message>
        <source>not a voxel-grid frame: a point array is not one value per voxel</source>
        <translation>不是体素网格帧：点数组并非每个体素一个值</translation>
    </message>
    <message>
        <source>not a particle frame: it has lines or polygons</source>
        <translation>不是粒子帧：其中含有线或多边形</translation>
    </message>
    <message>
        <source>particle seeding needs a positive spacing and 1 to 8 wall layers</source>
        <translation>粒子布置需要正的间距和 1 到 8 层壁面</translation>
    </message>
    <message>
        <source>an open end needs a unit normal, a positive radius and a positive buffer depth</source>
        <translation>开口端需要单位法向量、正的半径和正的缓冲深度</translation>
    </message>
    <message>
        <source>a vertex budget needs a positive area and vertex count</source>
        <translation>顶点预算需要正的面积和顶点数</translation>
    </message>
    <message>
        <source>vessel sizing needs centerlines with points</source>
        <translation>血管尺寸计算需要带点的中心线</translation>
    </message>
    <message>
        <source>the surface to remesh is empty</source>
        <translation>待重新网格化的表面为空</translation>
    </message>
    <message>
        <source>cannot write STL file</source>
        <translation>无法写入 STL 文件</translation>
    </message>
    <message>
        <source>array</source>
        <translation>数组</translation>
    </message>
    <message>
        <source>no boundary face of the mesh faces the lumen point; give a point inside the vessel&apos;s lumen</source>
        <translation>网格的边界面均不朝向管腔点；请给出血管管腔内的一点</translation>
    </message>
    <message>
        <source>say where the blood pressure acts: --pressure-array NAME (point data, nonzero on the lumen surface) or --lumen-point x,y,z (a point inside the lumen, mm)</source>
        <translation>请指明血压作用位置：--pressure-array NAME（点数据，在管腔表面非零）或 --lumen-point x,y,z（管腔内一点，mm）</translation>
    </message>
    <message>
        <source>say which nodes are held: --fixed-array NAME (point data, nonzero on held nodes) or --fix-open-ends (the end cuts at the lumen surface&apos;s open ends)</source>
        <translation>请指明固定的节点：--fixed-array NAME（点数据，在固定节点上非零）或 --fix-open-ends（管腔表面开口端的端部截面）</translation>
    </message>
    <message>
        <source>no boundary face is selected for the pressure: the wall would carry no load</source>
        <translation>没有为压力选择边界面：管壁将不承受任何载荷</translation>
    </message>
    <message>
        <source>the pressure would act on the whole boundary (inner, outer and end faces): the lumen surface is not parted from the rest by sharp edges; give --pressure-array</source>
        <translation>压力将作用于整个边界（内、外表面和端面）：管腔表面未被锐利边缘与其余部分分开；请给出 --pressure-array</translation>
    </message>
    <message>
        <source>the pressure surface is closed (no open ends): give the held nodes with --fixed-array</source>
        <translation>压力表面是封闭的（没有开口端）：请用 --fixed-array 给出固定节点</translation>
    </message>
    <message>
        <source>no node is held: the wall would float free</source>
        <translation>没有固定节点：管壁将自由漂移</translation>
    </message>
    <message>
        <source>the lumen surface is empty: extract the surface first</source>
        <translation>管腔表面为空：请先提取表面</translation>
    </message>
    <message>
        <source>a lumen vertex has no normal (degenerate surface)</source>
        <translation>有管腔顶点没有法向量（表面退化）</translation>
    </message>
    <message>
        <source>the tetrahedral mesh is not a vessel wall (no wall_layer field)</source>
        <translation>该四面体网格不是血管壁（没有 wall_layer 场）</translation>
    </message>
    <message>
        <source>no PDF to encapsulate</source>
        <translation>没有可封装的 PDF</translation>
    </message>
    <message>
        <source>cannot set the encapsulated document&apos;s length</source>
        <translation>无法设置封装文档的长度</translation>
    </message>
    <message>
        <source>cannot write the file</source>
        <translation>无法写入文件</translation>
    </message>
    <message>
        <source>the PDF could not be rendered (no fonts or no QGuiApplication)</source>
        <translation>无法生成 PDF（没有字体或没有 QGuiApplication）</translation>
    </message>
    <message>
        <source>cannot write the report</source>
        <translation>无法写入报告</translation>
    </message>
    <message>
        <source>run control: frame intervals must be &gt;= 0, keep_every and max_steps &gt;= 1</source>
        <translation>运行控制：帧间隔必须 &gt;= 0，keep_every 和 max_steps 必须 &gt;= 1</translation>
    </message>
    <message>
        <source>multigrid: the matrix, positions and constraints differ in size</source>
        <translation>多重网格：矩阵、位置与约束的大小不同</translation>
    </message>
    <message>
        <source>multigrid: the coarsest level is not positive definite</source>
        <translation>多重网格：最粗层不是正定的</translation>
    </message>
    <message>
        <source>the time step must be positive and the Rayleigh coefficients non-negative</source>
        <translation>时间步长必须为正，Rayleigh 系数不得为负</translation>
    </message>
    <message>
        <source>the external forces do not match the mesh</source>
        <translation>外力与网格不匹配</translation>
    </message>
    <message>
        <source>conjugate gradients: the matrix, right-hand side, guess and constraints differ in size</source>
        <translation>共轭梯度：矩阵、右端项、初值与约束的大小不同</translation>
    </message>
    <message>
        <source>the mesh has no elements</source>
        <translation>网格没有单元</translation>
    </message>
    <message>
        <source>the matrix does not have this mesh&apos;s pattern</source>
        <translation>矩阵不具有此网格的稀疏模式</translation>
    </message>
    <message>
        <source>this wall has an intraluminal thrombus layer, which the linear wall model (wall_model 0) cannot tell from the wall: run wall_model 1, or build the wall without --thrombus</source>
        <translation>该管壁含有腔内血栓层，线性管壁模型（wall_model 0）无法将其与管壁区分：请运行 wall_model 1，或不带 --thrombus 构建管壁</translation>
    </message>
    <message>
        <source>the physiological protocol needs centerlines (for the local diameter)</source>
        <translation>生理方案需要中心线（用于局部直径）</translation>
    </message>
    <message>
        <source>equilibrium_tolerance 0 (the damped path&apos;s last state) needs wall_model 0</source>
        <translation>equilibrium_tolerance 0（阻尼路径的最后状态）需要 wall_model 0</translation>
    </message>
    <message>
        <source>the wall has no element to take its peak stress from</source>
        <translation>管壁没有可取峰值应力的单元</translation>
    </message>
    <message>
        <source>GMRES: the matrix, right-hand side and constraints differ in size</source>
        <translation>GMRES：矩阵、右端项与约束的大小不同</translation>
    </message>
    <message>
        <source>hyperelastic polynomial material needs c10 + c01 &gt; 0, c20, c02 &gt;= 0 and a bulk modulus &gt; 0</source>
        <translation>超弹性多项式材料需要 c10 + c01 &gt; 0、c20、c02 &gt;= 0 以及体积模量 &gt; 0</translation>
    </message>
    <message>
        <source>the quadratic wall model needs a material</source>
        <translation>二次管壁模型需要材料</translation>
    </message>
    <message>
        <source>quasi-static tearing needs a ramp start &lt; end, a positive increment and tear strength, and an onset tolerance in (0, 0.5)</source>
        <translation>准静态撕裂需要斜坡起点 &lt; 终点、正的增量和撕裂强度，以及位于 (0, 0.5) 的起始容差</translation>
    </message>
    <message>
        <source>the element field does not match the mesh</source>
        <translation>单元场与网格不匹配</translation>
    </message>
    <message>
        <source>no element of the wall lies in the aneurysm sac: is the sac measured on the image this wall was built from?</source>
        <translation>管壁没有单元位于动脉瘤囊内：瘤囊是否是在构建该管壁的图像上测量的？</translation>
    </message>
    <message>
        <source>no step along the Newton direction keeps every element uninverted</source>
        <translation>沿牛顿方向的任何步长都无法保证所有单元不翻转</translation>
    </message>
    <message>
        <source>the static wall analysis needs a positive pressure and at least one load increment</source>
        <translation>静态管壁分析需要正的压力和至少一个载荷增量</translation>
    </message>
    <message>
        <source>a structured mesh needs at least one cell per axis</source>
        <translation>结构化网格每个轴至少需要一个单元</translation>
    </message>
    <message>
        <source>a tube wall needs 0 &lt; inner &lt; outer radius, a positive length and at least 3 cells around</source>
        <translation>管壁需要 0 &lt; 内半径 &lt; 外半径、正的长度以及周向至少 3 个单元</translation>
    </message>
    <message>
        <source>an annulus sector needs 0 &lt; inner &lt; outer radius, a positive angle and height</source>
        <translation>环形扇区需要 0 &lt; 内半径 &lt; 外半径、正的角度和高度</translation>
    </message>
    <message>
        <source>the tangent stiffness could not be factorised (a part of the wall is not held by the fixed ends, or the load is past the wall&apos;s limit)</source>
        <translation>切线刚度无法分解（部分管壁未被固定端约束，或载荷超过管壁极限）</translation>
    </message>
    <message>
        <source>tearing would remove every element of the wall</source>
        <translation>撕裂将移除管壁的所有单元</translation>
    </message>
    <message>
        <source>the tetrahedral mesh is not a vessel wall (wall_layer / end_set fields missing): build it with &apos;mesh wall&apos;</source>
        <translation>该四面体网格不是血管壁（缺少 wall_layer / end_set 场）：请用 &apos;mesh wall&apos; 构建</translation>
    </message>
    <message>
        <source>the wall has no fixed end (end_set is 0 everywhere): build it from centerlines with ends</source>
        <translation>管壁没有固定端（end_set 处处为 0）：请由带端点的中心线构建</translation>
    </message>
    <message>
        <source>no lumen face carries the pressure</source>
        <translation>没有管腔面承受压力</translation>
    </message>
    <message>
        <source>the run has no pressure curve</source>
        <translation>该运行没有压力曲线</translation>
    </message>
    <message>
        <source>dragging the wall needs the CPU backend (the GPU stepper has no contact springs)</source>
        <translation>拖动管壁需要 CPU 后端（GPU 步进器没有接触弹簧）</translation>
    </message>
    <message>
        <source>the heat solver takes no input (its cube comes from the parameters)</source>
        <translation>热求解器不接受输入（其立方体来自参数）</translation>
    </message>
    <message>
        <source>the injection rate must be positive</source>
        <translation>注射速率必须为正</translation>
    </message>
    <message>
        <source>the arterial inflow must be positive</source>
        <translation>动脉流入量必须为正</translation>
    </message>
    <message>
        <source>the catheter&apos;s radius and the viscosities must be positive</source>
        <translation>导管半径和黏度必须为正</translation>
    </message>
    <message>
        <source>the filling takes no input: its network comes with the solved run</source>
        <translation>充盈计算不接受输入：其网络来自已求解的运行</translation>
    </message>
    <message>
        <source>the flow system is singular: the part downstream of the tip has no outlet pressure to refer to</source>
        <translation>流动方程组奇异：导管尖端下游部分没有可参照的出口压力</translation>
    </message>
    <message>
        <source>the injection needs a positive rate or a tip pressure</source>
        <translation>注射需要正的速率或尖端压力</translation>
    </message>
    <message>
        <source>feeder edit: there is no lesion for a feeder to feed</source>
        <translation>供血支编辑：没有可供血的病灶</translation>
    </message>
    <message>
        <source>the centerlines have no vessel segments: extract them first (vascusim-cli centerline)</source>
        <translation>中心线中没有血管节段：请先提取（vascusim-cli centerline）</translation>
    </message>
    <message>
        <source>feeders are edited on a run with a liver label: give the liver (and the tumour) first</source>
        <translation>供血支需在带肝脏标签的运行上编辑：请先给出肝脏（和肿瘤）</translation>
    </message>
    <message>
        <source>a tip pressure drives the injected drug alone (blood_flow=0); with blood flow the injection is a rate</source>
        <translation>尖端压力仅驱动注入的药物（blood_flow=0）；有血流时注射以速率给出</translation>
    </message>
    <message>
        <source>the tip pressure does not drive any flow into the network (it is at or below the outlets&apos;)</source>
        <translation>尖端压力未能驱动任何流量进入网络（其等于或低于出口压力）</translation>
    </message>
    <message>
        <source>the tumour&apos;s radius must be positive</source>
        <translation>肿瘤半径必须为正</translation>
    </message>
    <message>
        <source>the liver label has no voxel of the liver&apos;s value</source>
        <translation>肝脏标签中没有肝脏取值的体素</translation>
    </message>
    <message>
        <source>no end of the vessel tree lies in the liver: there is no territory to share out</source>
        <translation>血管树没有末端位于肝内：没有可划分的供血区域</translation>
    </message>
    <message>
        <source>parameter</source>
        <translation>参数</translation>
    </message>
    <message>
        <source>phase densities and viscosities must be positive</source>
        <translation>各相的密度和黏度必须为正</translation>
    </message>
    <message>
        <source>the working angle needs a tip away from the root: there is no path to see</source>
        <translation>工作角度需要远离根部的尖端：没有可观察的路径</translation>
    </message>
    <message>
        <source>the endoscope camera is outside the smoke&apos;s domain or inside tissue</source>
        <translation>内镜相机位于烟雾区域之外或组织内</translation>
    </message>
    <message>
        <source>the liver label is empty: the liver-ablation dome needs the liver&apos;s surface</source>
        <translation>肝脏标签为空：肝消融穹顶需要肝脏表面</translation>
    </message>
    <message>
        <source>the EVH tunnel needs a centerline of 20 mm or more</source>
        <translation>EVH 隧道需要 20 mm 或更长的中心线</translation>
    </message>
    <message>
        <source>a suction needs a vent or an open face for the gas it takes out to be replaced</source>
        <translation>抽吸需要通气口或开放面，以补充被抽出的气体</translation>
    </message>
    <message>
        <source>the suction port has no fluid cell within its radius</source>
        <translation>抽吸口半径内没有流体单元</translation>
    </message>
    <message>
        <source>the dam break needs a positive particle spacing</source>
        <translation>溃坝算例需要正的粒子间距</translation>
    </message>
    <message>
        <source>the dam break needs at least 1000 particles</source>
        <translation>溃坝算例至少需要 1000 个粒子</translation>
    </message>
    <message>
        <source>sph-fpm: the moment matrix is singular at a particle next to the wall</source>
        <translation>sph-fpm：壁面附近某粒子的矩矩阵奇异</translation>
    </message>
    <message>
        <source>sph-fpm: no particle next to the wall was evaluated</source>
        <translation>sph-fpm：未评估任何壁面附近的粒子</translation>
    </message>
    <message>
        <source>the neighbour grid&apos;s reach must be a positive length</source>
        <translation>邻域网格的作用范围必须为正长度</translation>
    </message>
    <message>
        <source>a particle&apos;s position is not finite: the neighbour grid cannot place it</source>
        <translation>有粒子位置不是有限值：邻域网格无法放置它</translation>
    </message>
    <message>
        <source>the SPH smoothing length must be a positive length</source>
        <translation>SPH 光滑长度必须为正长度</translation>
    </message>
    <message>
        <source>the SPH input&apos;s particles need the field &apos;wall&apos; (1 at wall particles, 0 in the fluid)</source>
        <translation>SPH 输入的粒子需要 &apos;wall&apos; 场（壁面粒子为 1，流体中为 0）</translation>
    </message>
    <message>
        <source>the SPH input has no particles</source>
        <translation>SPH 输入没有粒子</translation>
    </message>
    <message>
        <source>the stenosis figures need one averaged flow per section</source>
        <translation>狭窄指标需要每个截面一个平均流量</translation>
    </message>
    <message>
        <source>a section the stenosis is compared with holds no fluid</source>
        <translation>与狭窄比较的截面中没有流体</translation>
    </message>
    <message>
        <source>kind</source>
        <translation>类型</translation>
    </message>
    <message>
        <source>cannot write skeleton</source>
        <translation>无法写入骨架</translation>
    </message>
    <message>
        <source>cannot write the measurement</source>
        <translation>无法写入测量</translation>
    </message>
    <message>
        <source>cannot parse skeleton</source>
        <translation>无法解析骨架</translation>
    </message>
    <message>
        <source>cannot parse the measurement</source>
        <translation>无法解析测量</translation>
    </message>
    <message>
        <source>unknown artifact kind</source>
        <translation>未知的工件类型</translation>
    </message>
    <message>
        <source>the mask has no labelled voxel</source>
        <translation>掩模中没有已标记的体素</translation>
    </message>
    <message>
        <source>study.json is not a VascuSim study manifest</source>
        <translation>study.json 不是 VascuSim 研究清单</translation>
    </message>
    <message>
        <source>software_version</source>
        <translation>软件版本</translation>
    </message>
    <message>
        <source>study.json is malformed</source>
        <translation>study.json 格式错误</translation>
    </message>
    <message>
        <source>the mesh file does not exist</source>
        <translation>网格文件不存在</translation>
    </message>
    <message>
        <source>not a VTK XML unstructured grid (.vtu)</source>
        <translation>不是 VTK XML 非结构化网格（.vtu）</translation>
    </message>
    <message>
        <source>the mesh has no tetrahedra</source>
        <translation>网格没有四面体</translation>
    </message>
    <message>
        <source>a position must be [x, y, z] in mm</source>
        <translation>位置必须是以 mm 为单位的 [x, y, z]</translation>
    </message>
    <message>
        <source>not a vascusim network file (&quot;format&quot;: &quot;vascusim-network&quot; is missing)</source>
        <translation>不是 VascuSim 网络文件（缺少 &quot;format&quot;: &quot;vascusim-network&quot;）</translation>
    </message>
    <message>
        <source>unsupported network file version (this build reads version 1)</source>
        <translation>不支持的网络文件版本（本版本读取版本 1）</translation>
    </message>
    <message>
        <source>network file not found</source>
        <translation>未找到网络文件</translation>
    </message>
    <message>
        <source>cannot write the network file</source>
        <translation>无法写入网络文件</translation>
    </message>
    <message>
        <source>a run frame of an unknown format</source>
        <translation>运行帧的格式未知</translation>
    </message>
    <message>
        <source>not a run this VascuSim reads</source>
        <translation>不是本 VascuSim 可读取的运行</translation>
    </message>
    <message>
        <source>cannot parse a run&apos;s run.json</source>
        <translation>无法解析运行的 run.json</translation>
    </message>
    <message>
        <source>a run is written with its frames in memory</source>
        <translation>运行需在其帧位于内存中时写入</translation>
    </message>
    <message>
        <source>a run&apos;s run.json lacks an entry</source>
        <translation>运行的 run.json 缺少条目</translation>
    </message>
    <message>
        <source>the folder is a study already; open it instead of creating a new one</source>
        <translation>该文件夹已是一个研究；请打开它，而不是新建</translation>
    </message>
    <message>
        <source>the folder became a study while waiting for its lock; open it instead</source>
        <translation>等待锁期间该文件夹已成为研究；请改为打开它</translation>
    </message>
    <message>
        <source>not a VascuSim study: study.json is missing</source>
        <translation>不是 VascuSim 研究：缺少 study.json</translation>
    </message>
    <message>
        <source>cannot add an empty image to the study</source>
        <translation>无法向研究添加空图像</translation>
    </message>
    <message>
        <source>cannot add an empty label volume to the study</source>
        <translation>无法向研究添加空标签体积</translation>
    </message>
    <message>
        <source>cannot add an empty surface to the study</source>
        <translation>无法向研究添加空表面</translation>
    </message>
    <message>
        <source>cannot add an empty tetrahedral mesh to the study</source>
        <translation>无法向研究添加空四面体网格</translation>
    </message>
    <message>
        <source>cannot add an empty vessel network to the study</source>
        <translation>无法向研究添加空血管网络</translation>
    </message>
    <message>
        <source>a run added to the study needs its frames</source>
        <translation>添加到研究的运行需要其帧</translation>
    </message>
    <message>
        <source>a report added to the study must be a PDF</source>
        <translation>添加到研究的报告必须是 PDF</translation>
    </message>
    <message>
        <source>the study is open read-only; save it under a new name, or reopen it for writing when its writer has finished</source>
        <translation>该研究以只读方式打开；请另存为新名称，或在其写入者完成后重新以可写方式打开</translation>
    </message>
    <message>
        <source>study.json was changed by another program since this study was opened; nothing was written. Save under a new name (Save As) to keep this version</source>
        <translation>自打开该研究以来 study.json 已被其他程序修改；未写入任何内容。请以新名称保存（另存为）以保留此版本</translation>
    </message>
    <message>
        <source>the folder for the new study is not empty; choose a new folder</source>
        <translation>新研究的文件夹不为空；请选择新的文件夹</translation>
    </message>
    <message>
        <source>holder</source>
        <translation>持有者</translation>
    </message>
    <message>
        <source>host</source>
        <translation>主机</translation>
    </message>
    <message>
        <source>not a NIfTI, NRRD or MetaImage volume (or the file cannot be read)</source>
        <translation>不是 NIfTI、NRRD 或 MetaImage 体积（或文件无法读取）</translation>
    </message>
    <message>
        <source>cannot read the volume</source>
        <translation>无法读取体积</translation>
    </message>
    <message>
        <source>the volume file is truncated: it holds fewer bytes than its header announces</source>
        <translation>体积文件被截断：其字节数少于文件头声明的数量</translation>
    </message>
    <message>
        <source>bytes</source>
        <translation>字节数</translation>
    </message>
    <message>
        <source>voxel bytes expected</source>
        <translation>预期体素字节数</translation>
    </message>
    <message>
        <source>volume file does not exist</source>
        <translation>体积文件不存在</translation>
    </message>
    <message>
        <source>cannot read the volume header</source>
        <translation>无法读取体积文件头</translation>
    </message>
    <message>
        <source>the volume is not 3D</source>
        <translation>该体积不是三维的</translation>
    </message>
    <message>
        <source>dimensions</source>
        <translation>维度</translation>
    </message>
    <message>
        <source>the volume has more than one component per voxel (colour or vector data)</source>
        <translation>该体积每个体素有多个分量（彩色或矢量数据）</translation>
    </message>
    <message>
        <source>components</source>
        <translation>分量</translation>
    </message>
    <message>
        <source>cannot write VTK XML file</source>
        <translation>无法写入 VTK XML 文件</translation>
    </message>
    <message>
        <source>file does not exist</source>
        <translation>文件不存在</translation>
    </message>
    <message>
        <source>cannot read VTK XML file</source>
        <translation>无法读取 VTK XML 文件</translation>
    </message>
    <message>
        <source>field lines need one value (and radius pair) per line</source>
        <translation>场线每条线需要一个值（及一对半径）</translation>
    </message>
    <message>
        <source>3D snapshots need a display (set DISPLAY, or run under xvfb-run)</source>
        <translation>3D 快照需要显示器（请设置 DISPLAY，或在 xvfb-run 下运行）</translation>
    </message>
    <message>
        <source>a snapshot needs at least 16 x 16 pixels</source>
        <translation>快照至少需要 16 x 16 像素</translation>
    </message>
    <message>
        <source>the offscreen snapshot could not be read back</source>
        <translation>无法读回离屏快照</translation>
    </message>
    <message>
        <source>field points need one value per point</source>
        <translation>场点每个点需要一个值</translation>
    </message>
    <message>
        <source>unknown backend &apos;%1&apos; (auto, cpu, cuda)</source>
        <translation>未知后端 &apos;%1&apos;（auto、cpu、cuda）</translation>
    </message>
    <message>
        <source>%1: use --backend cpu or auto</source>
        <translation>%1：请使用 --backend cpu 或 auto</translation>
    </message>
    <message>
        <source>this series is already in the study, as %1 (%2): it is not imported twice</source>
        <translation>该序列已在研究中，为 %1（%2）：不会重复导入</translation>
    </message>
    <message>
        <source>no series &apos;%1&apos; among the %2 series found (see --list)</source>
        <translation>在找到的 %2 个序列中没有序列 &apos;%1&apos;（见 --list）</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not %2 numbers separated by commas</source>
        <translation>&apos;%1&apos; 不是以逗号分隔的 %2 个数字</translation>
    </message>
    <message>
        <source>the needle&apos;s bore (%1 mm) needs at least two particles across: a spacing of at most %2 mm</source>
        <translation>针孔（%1 mm）横截面至少需要两个粒子：间距最多 %2 mm</translation>
    </message>
    <message>
        <source>the tumour volume has no voxel of value %1</source>
        <translation>肿瘤体积中没有值为 %1 的体素</translation>
    </message>
    <message>
        <source>the tumour must be a label or image artifact, not a %1</source>
        <translation>肿瘤必须是标签或图像工件，而不是 %1</translation>
    </message>
    <message>
        <source>the %1 must be a label or image artifact, not a %2</source>
        <translation>%1 必须是标签或图像工件，而不是 %2</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a segment number (feeders.csv lists them)</source>
        <translation>%1：&apos;%2&apos; 不是节段编号（见 feeders.csv）</translation>
    </message>
    <message>
        <source>no such segment: the centerlines have segments 0 to %1</source>
        <translation>没有该节段：中心线的节段编号为 0 到 %1</translation>
    </message>
    <message>
        <source>unknown smoke scenario &apos;%1&apos; (ball-drop, evh, liver-ablation)</source>
        <translation>未知烟雾场景 &apos;%1&apos;（ball-drop、evh、liver-ablation）</translation>
    </message>
    <message>
        <source>the vessel ends %1 and %2 are not connected</source>
        <translation>血管末端 %1 与 %2 不相连</translation>
    </message>
    <message>
        <source>the centerlines &apos;%1&apos; have no lumen label to fill with particles</source>
        <translation>中心线 &apos;%1&apos; 没有可填充粒子的管腔标签</translation>
    </message>
    <message>
        <source>the vessels need at least two open ends (%1&apos;s and an outlet); the centerlines have %2</source>
        <translation>血管至少需要两个开口端（%1 的及一个出口）；中心线有 %2 个</translation>
    </message>
    <message>
        <source>%1&apos;s node %2 is not a vessel end (ends: %3)</source>
        <translation>%1 的节点 %2 不是血管末端（末端：%3）</translation>
    </message>
    <message>
        <source>unknown report section &apos;%1&apos;; sections: aaa, stenosis, chemoembolization, smoke, measurements, runs</source>
        <translation>未知报告章节 &apos;%1&apos;；章节：aaa、stenosis、chemoembolization、smoke、measurements、runs</translation>
    </message>
    <message>
        <source>unknown language &apos;%1&apos;; use en, de, zh_CN or a catalogue file (.qm)</source>
        <translation>未知语言 &apos;%1&apos;；请使用 en、de、zh_CN 或目录文件（.qm）</translation>
    </message>
    <message>
        <source>the %1 catalogue is missing from this build (:/i18n/vascusim_%2.qm)</source>
        <translation>本版本缺少 %1 目录（:/i18n/vascusim_%2.qm）</translation>
    </message>
    <message>
        <source>the frame has no cell field &apos;%1&apos;</source>
        <translation>该帧没有单元场 &apos;%1&apos;</translation>
    </message>
    <message>
        <source>unknown protocol &apos;%1&apos; (thesis-rupture, physiological, interactive)</source>
        <translation>未知方案 &apos;%1&apos;（thesis-rupture、physiological、interactive）</translation>
    </message>
    <message>
        <source>could not write %1</source>
        <translation>无法写入 %1</translation>
    </message>
    <message>
        <source>the outbox folder exists already: %1</source>
        <translation>发件箱文件夹已存在：%1</translation>
    </message>
    <message>
        <source>could not write the movie frame %1</source>
        <translation>无法写入影片帧 %1</translation>
    </message>
    <message>
        <source>CUDA call failed: %1: %2</source>
        <translation>CUDA 调用失败：%1：%2</translation>
    </message>
    <message>
        <source>the CUDA SPH backend takes at most %1 open boundaries; this case has %2</source>
        <translation>CUDA SPH 后端最多支持 %1 个开放边界；此算例有 %2 个</translation>
    </message>
    <message>
        <source>the CUDA SPH backend does not carry a tracer yet: inlet &apos;%1&apos; lets one in; run this case on the CPU (--backend cpu)</source>
        <translation>CUDA SPH 后端尚不支持示踪剂：入口 &apos;%1&apos; 会引入示踪剂；请在 CPU 上运行此算例（--backend cpu）</translation>
    </message>
    <message>
        <source>the SPH domain spans too many cells for the GPU grid: %1</source>
        <translation>SPH 区域的单元数超出 GPU 网格容量：%1</translation>
    </message>
    <message>
        <source>the study has no artifact &apos;%1&apos;</source>
        <translation>该研究没有工件 &apos;%1&apos;</translation>
    </message>
    <message>
        <source>a UID root is digits in components separated by dots, without leading zeros, at most 32 characters (e.g. 1.2.826.0.1.3680043.10.1234), not &apos;%1&apos;</source>
        <translation>UID 根由以点分隔的数字组成，不含前导零，最多 32 个字符（如 1.2.826.0.1.3680043.10.1234），而不是 &apos;%1&apos;</translation>
    </message>
    <message>
        <source>the values are not CT Hounsfield units: %1%2</source>
        <translation>这些值不是 CT 亨氏单位：%1%2</translation>
    </message>
    <message>
        <source>cannot create the output folder: %1 is a file</source>
        <translation>无法创建输出文件夹：%1 是一个文件</translation>
    </message>
    <message>
        <source>the output folder is VascuSim&apos;s %1 folder, not a %2 folder; choose a new or empty folder</source>
        <translation>输出文件夹是 VascuSim 的 %1 文件夹，而不是 %2 文件夹；请选择新的或空的文件夹</translation>
    </message>
    <message>
        <source>cannot create the output folder: %1</source>
        <translation>无法创建输出文件夹：%1</translation>
    </message>
    <message>
        <source>unknown parameter &apos;%1&apos;</source>
        <translation>未知参数 &apos;%1&apos;</translation>
    </message>
    <message>
        <source>parameter &apos;%1&apos; is not a finite number</source>
        <translation>参数 &apos;%1&apos; 不是有限数</translation>
    </message>
    <message>
        <source>parameter &apos;%1&apos; = %2 is outside its range %3</source>
        <translation>参数 &apos;%1&apos; = %2 超出其范围 %3</translation>
    </message>
    <message>
        <source>parameter &apos;%1&apos; must be a whole number, got %2</source>
        <translation>参数 &apos;%1&apos; 必须为整数，得到 %2</translation>
    </message>
    <message>
        <source>expected key=value, got &apos;%1&apos;</source>
        <translation>应为 key=value，得到 &apos;%1&apos;</translation>
    </message>
    <message>
        <source>parameter &apos;%1&apos; needs a number, got &apos;%2&apos;</source>
        <translation>参数 &apos;%1&apos; 需要一个数字，得到 &apos;%2&apos;</translation>
    </message>
    <message>
        <source>the particle field %1 has %2 values for %3 particles</source>
        <translation>粒子场 %1 有 %2 个值，而粒子数为 %3</translation>
    </message>
    <message>
        <source>the solver needs a %1 as its input &apos;%2&apos;, and none was given</source>
        <translation>求解器需要 %1 作为输入 &apos;%2&apos;，但未提供</translation>
    </message>
    <message>
        <source>the solver&apos;s input &apos;%1&apos; must be a %2, not a %3</source>
        <translation>求解器输入 &apos;%1&apos; 必须是 %2，而不是 %3</translation>
    </message>
    <message>
        <source>node %1 has a position that is not a number</source>
        <translation>节点 %1 的位置不是数字</translation>
    </message>
    <message>
        <source>%1 refers to a node that does not exist</source>
        <translation>%1 引用了不存在的节点</translation>
    </message>
    <message>
        <source>%1 starts and ends at node %2</source>
        <translation>%1 的起点和终点都是节点 %2</translation>
    </message>
    <message>
        <source>%1 has a length that is not positive</source>
        <translation>%1 的长度不为正</translation>
    </message>
    <message>
        <source>%1 has a negative or invalid resistance</source>
        <translation>%1 的阻力为负或无效</translation>
    </message>
    <message>
        <source>%1 has a radius that is zero or negative (%2, %3 mm)</source>
        <translation>%1 的半径为零或负（%2、%3 mm）</translation>
    </message>
    <message>
        <source>%1 (nodes %2 - %3) closes a cycle: the network must be a tree</source>
        <translation>%1（节点 %2 - %3）形成了环路：网络必须是树</translation>
    </message>
    <message>
        <source>an outlet condition names node %1, which does not exist</source>
        <translation>出口条件指定的节点 %1 不存在</translation>
    </message>
    <message>
        <source>the outlet at node %1 has a pressure that is not a number</source>
        <translation>节点 %1 处出口的压力不是数字</translation>
    </message>
    <message>
        <source>the outlet at node %1 has a negative or invalid resistance</source>
        <translation>节点 %1 处出口的阻力为负或无效</translation>
    </message>
    <message>
        <source>the network&apos;s root is node %1, which does not exist</source>
        <translation>网络的根节点 %1 不存在</translation>
    </message>
    <message>
        <source>segment field &apos;%1&apos; has %2 values for %3 segments</source>
        <translation>节段场 &apos;%1&apos; 有 %2 个值，而节段数为 %3</translation>
    </message>
    <message>
        <source>unknown measurement kind &apos;%1&apos; (ruler, angle or roi)</source>
        <translation>未知测量类型 &apos;%1&apos;（ruler、angle 或 roi）</translation>
    </message>
    <message>
        <source>the %1 phantom exists in the analytic style only (--style analytic)</source>
        <translation>%1 体模仅有解析样式（--style analytic）</translation>
    </message>
    <message>
        <source>unknown transfer syntax &apos;%1&apos;; known: explicit-le, implicit-le, jpeg-lossless, jpeg-ls, rle, jpeg-extended</source>
        <translation>未知传输语法 &apos;%1&apos;；已知：explicit-le、implicit-le、jpeg-lossless、jpeg-ls、rle、jpeg-extended</translation>
    </message>
    <message>
        <source>unsupported pixel layout: %1 bits allocated</source>
        <translation>不支持的像素布局：分配位数 %1</translation>
    </message>
    <message>
        <source>invalid Number of Frames: %1</source>
        <translation>无效的 Number of Frames：%1</translation>
    </message>
    <message>
        <source>the series needs %1 of memory for %2 x %3 x %4 voxels, but only %5 is available</source>
        <translation>该序列的 %2 x %3 x %4 个体素需要 %1 内存，但只有 %5 可用</translation>
    </message>
    <message>
        <source>cannot decode image %1 of the series: %2</source>
        <translation>无法解码该序列的图像 %1：%2</translation>
    </message>
    <message>
        <source>the DICOM SEG has no %1 for every frame: its geometry is unknown</source>
        <translation>DICOM SEG 并非每帧都有 %1：其几何未知</translation>
    </message>
    <message>
        <source>cannot read %1 as DICOM</source>
        <translation>无法将 %1 作为 DICOM 读取</translation>
    </message>
    <message>
        <source>%1 is not a DICOM Segmentation object (SOP class %2)</source>
        <translation>%1 不是 DICOM 分割对象（SOP 类 %2）</translation>
    </message>
    <message>
        <source>the DICOM SEG&apos;s image description is incomplete or unsupported (rows %1, columns %2, frames %3, %4 bits, type %5)</source>
        <translation>DICOM SEG 的图像描述不完整或不受支持（行 %1、列 %2、帧 %3、%4 位、类型 %5）</translation>
    </message>
    <message>
        <source>frame %1 of the DICOM SEG names no segment (1..255)</source>
        <translation>DICOM SEG 的帧 %1 未指定分割段（1..255）</translation>
    </message>
    <message>
        <source>the DICOM SEG&apos;s frames are not a regular stack (positions along the normal are not whole multiples of %1 mm apart)</source>
        <translation>DICOM SEG 的帧不是规则堆栈（沿法向的位置间距不是 %1 mm 的整数倍）</translation>
    </message>
    <message>
        <source>the DICOM SEG&apos;s grid is too large (%1 x %2 x %3 voxels)</source>
        <translation>DICOM SEG 的网格过大（%1 x %2 x %3 个体素）</translation>
    </message>
    <message>
        <source>the DICOM SEG&apos;s pixel data is shorter than its frames (%1 of %2 bytes)</source>
        <translation>DICOM SEG 的像素数据短于其帧（%2 字节中只有 %1）</translation>
    </message>
    <message>
        <source>writing the DICOM SEG failed at %1: %2</source>
        <translation>写入 DICOM SEG 时在 %1 处失败：%2</translation>
    </message>
    <message>
        <source>writing the DICOM SEG failed at the derivation image of slice %1</source>
        <translation>写入 DICOM SEG 时在层面 %1 的派生图像处失败</translation>
    </message>
    <message>
        <source>writing the DICOM SEG failed: segment %1 for label value %2</source>
        <translation>写入 DICOM SEG 失败：标签值 %2 对应的分割段 %1</translation>
    </message>
    <message>
        <source>AE titles have 1 to 16 characters (PACS &apos;%1&apos;, ours &apos;%2&apos;)</source>
        <translation>AE 标题为 1 到 16 个字符（PACS &apos;%1&apos;，本机 &apos;%2&apos;）</translation>
    </message>
    <message>
        <source>a PACS node needs a host and a port from 1 to 65535 (%1)</source>
        <translation>PACS 节点需要主机和 1 到 65535 之间的端口（%1）</translation>
    </message>
    <message>
        <source>the PACS %1 rejected the association: is our AE title &apos;%2&apos; registered there, and is its own &apos;%3&apos;?</source>
        <translation>PACS %1 拒绝了关联：本机 AE 标题 &apos;%2&apos; 是否已在其处注册，其自身标题是否为 &apos;%3&apos;？</translation>
    </message>
    <message>
        <source>the PACS %1 took the connection but did not answer within %2 s (is it a DICOM node, is the port its DICOM port, and does it speak DICOM TLS there?)</source>
        <translation>PACS %1 接受了连接，但未在 %2 秒内应答（它是否为 DICOM 节点，该端口是否为其 DICOM 端口，且是否在该端口使用 DICOM TLS？）</translation>
    </message>
    <message>
        <source>the PACS %1 took the connection but did not answer within %2 s (is it a DICOM node, and is the port its DICOM port?)</source>
        <translation>PACS %1 接受了连接，但未在 %2 秒内应答（它是否为 DICOM 节点，该端口是否为其 DICOM 端口？）</translation>
    </message>
    <message>
        <source>could not connect over DICOM TLS (%1): %2 (does the PACS speak TLS on this port, is its certificate among those we trust (%3), and does it trust ours?)</source>
        <translation>无法通过 DICOM TLS 连接（%1）：%2（PACS 是否在此端口使用 TLS，其证书是否在我们信任的证书中（%3），且它是否信任我们的证书？）</translation>
    </message>
    <message>
        <source>the PACS %1 does not offer %2</source>
        <translation>PACS %1 不提供 %2</translation>
    </message>
    <message>
        <source>%1 (%2): %3</source>
        <translation>%1（%2）：%3</translation>
    </message>
    <message>
        <source>the retrieve&apos;s folder is not empty: %1</source>
        <translation>检索文件夹不为空：%1</translation>
    </message>
    <message>
        <source>cannot create the retrieve&apos;s folder %1: %2</source>
        <translation>无法创建检索文件夹 %1：%2</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <source>the move&apos;s listening port must be from 1 to 65535, not %1</source>
        <translation>移动的监听端口必须在 1 到 65535 之间，而不是 %1</translation>
    </message>
    <message>
        <source>cannot listen on port %1 for the move: %2 (is another program using it?)</source>
        <translation>无法在端口 %1 上为移动监听：%2（是否有其他程序占用？）</translation>
    </message>
    <message>
        <source>not a DICOM file: %1 (%2)</source>
        <translation>不是 DICOM 文件：%1（%2）</translation>
    </message>
    <message>
        <source>a DICOM object to store needs its SOP class, instance and study UIDs: %1</source>
        <translation>待存储的 DICOM 对象需要其 SOP 类、实例 UID 和研究 UID：%1</translation>
    </message>
    <message>
        <source>%1 is de-identified (Patient Identity Removed YES, e.g. a report made with --anonymize): it is not stored into a patient&apos;s study. Nothing was sent; to store it as a new anonymized study, ask for that (pacs store --anonymized new-study)</source>
        <translation>%1 已去标识化（Patient Identity Removed YES，例如用 --anonymize 生成的报告）：不会存入患者的研究。未发送任何内容；如需作为新的匿名研究存储，请明确指定（pacs store --anonymized new-study）</translation>
    </message>
    <message>
        <source>the store of %1 broke off (%2): %3; %4</source>
        <translation>%1 的存储中断（%2）：%3；%4</translation>
    </message>
    <message>
        <source>the PACS %1 refused %2 with status %3; %4</source>
        <translation>PACS %1 以状态 %3 拒绝了 %2；%4</translation>
    </message>
    <message>
        <source>DICOM TLS: %1: %2</source>
        <translation>DICOM TLS：%1：%2</translation>
    </message>
    <message>
        <source>DICOM TLS needs %1 (a PEM file)</source>
        <translation>DICOM TLS 需要 %1（PEM 文件）</translation>
    </message>
    <message>
        <source>DICOM TLS: %1 is not a file: %2</source>
        <translation>DICOM TLS：%1 不是文件：%2</translation>
    </message>
    <message>
        <source>DICOM TLS: the private key %1 is not that of the certificate %2</source>
        <translation>DICOM TLS：私钥 %1 与证书 %2 不匹配</translation>
    </message>
    <message>
        <source>unknown phantom kind &apos;%1&apos;; known kinds: aaa, stenosis, hepatic-tree, bifurcation</source>
        <translation>未知体模类型 &apos;%1&apos;；已知类型：aaa、stenosis、hepatic-tree、bifurcation</translation>
    </message>
    <message>
        <source>unknown phantom style &apos;%1&apos;; known styles: patient, analytic</source>
        <translation>未知体模样式 &apos;%1&apos;；已知样式：patient、analytic</translation>
    </message>
    <message>
        <source>the vessel label is disconnected: skeleton nodes %1 and %2 cannot be reached from the root through the lumen; segment one vessel tree from a seed, or join the parts with the brush</source>
        <translation>血管标签不连通：骨架节点 %1 和 %2 无法从根部经管腔到达；请从一个种子点分割单一血管树，或用画笔连接各部分</translation>
    </message>
    <message>
        <source>the centerline is shorter than one step (%1 mm)</source>
        <translation>中心线短于一个步长（%1 mm）</translation>
    </message>
    <message>
        <source>the point %1 lies outside the image; pick it on the images</source>
        <translation>点 %1 位于图像之外；请在图像上选取</translation>
    </message>
    <message>
        <source>no tissue darker than the point %1 around it (%2 HU): is it inside a vessel, and is the image contrast-enhanced CT?</source>
        <translation>点 %1 周围没有比它更暗的组织（%2 HU）：它是否在血管内，图像是否为增强 CT？</translation>
    </message>
    <message>
        <source>the point %1 is not in a contrast-filled vessel (%2 HU against %3 HU around it); pick a point inside the lumen</source>
        <translation>点 %1 不在造影剂充盈的血管内（%2 HU，周围为 %3 HU）；请在管腔内选点</translation>
    </message>
    <message>
        <source>unknown segmentation target &apos;%1&apos;; known targets: aorta, hepatic, all</source>
        <translation>未知分割目标 &apos;%1&apos;；已知目标：aorta、hepatic、all</translation>
    </message>
    <message>
        <source>the intensities are not CT Hounsfield units (%1): import the CT rescaled to HU (vascusim-cli import --rescale SLOPE,INTERCEPT), not MR</source>
        <translation>强度值不是 CT 亨氏单位（%1）：请导入换算为 HU 的 CT（vascusim-cli import --rescale SLOPE,INTERCEPT），而非 MR</translation>
    </message>
    <message>
        <source>the points&apos; tissue (%1 HU) lies within the liver&apos;s own range (%2 +/- %3 HU): place them in the lesion&apos;s darker (or brighter) part, or lower lesion_sigmas</source>
        <translation>这些点处的组织（%1 HU）落在肝脏自身范围内（%2 +/- %3 HU）：请将点放在病灶较暗（或较亮）的部分，或降低 lesion_sigmas</translation>
    </message>
    <message>
        <source>the seed (%1, %2, %3) mm lies outside the image: click inside a vessel</source>
        <translation>种子点 (%1, %2, %3) mm 位于图像之外：请点击血管内部</translation>
    </message>
    <message>
        <source>the seed is not in a contrast-filled vessel: %1 HU there, outside %2..%3 HU; click inside a bright vessel or change min_contrast_hu / max_contrast_hu</source>
        <translation>种子点不在造影剂充盈的血管内：该处为 %1 HU，不在 %2..%3 HU 内；请点击明亮的血管或修改 min_contrast_hu / max_contrast_hu</translation>
    </message>
    <message>
        <source>no contrast-filled vessel found (no thick region of %1..%2 HU): is this a contrast-enhanced CTA? Give a seed inside a vessel or lower min_contrast_hu</source>
        <translation>未找到造影剂充盈的血管（没有 %1..%2 HU 的较厚区域）：这是增强 CTA 吗？请在血管内给出种子点或降低 min_contrast_hu</translation>
    </message>
    <message>
        <source>the seed lies where the smoothed image is below the vessel boundary (%1 HU): click nearer the centre of the vessel</source>
        <translation>种子点处的平滑图像低于血管边界（%1 HU）：请点击更靠近血管中心的位置</translation>
    </message>
    <message>
        <source>a %1 takes %2 points</source>
        <translation>%1 需要 %2 个点</translation>
    </message>
    <message>
        <source>not a vessel network frame: the array %1 is missing</source>
        <translation>不是血管网络帧：缺少数组 %1</translation>
    </message>
    <message>
        <source>the label has no lumen voxels (value %1) to fill with particles</source>
        <translation>标签中没有可填充粒子的管腔体素（值 %1）</translation>
    </message>
    <message>
        <source>a particle spacing of %1 mm needs %2 lattice points over the lumen: choose a larger spacing</source>
        <translation>%1 mm 的粒子间距需要在管腔上布置 %2 个格点：请选择更大的间距</translation>
    </message>
    <message>
        <source>the mesh has no point-data array &apos;%1&apos; for %2 (its arrays: %3)</source>
        <translation>网格没有用于 %2 的点数据数组 &apos;%1&apos;（现有数组：%3）</translation>
    </message>
    <message>
        <source>the vessel end %1 cuts no triangle of the lumen surface: is the surface from the same label as the centerlines?</source>
        <translation>血管末端 %1 未切割管腔表面的任何三角形：表面与中心线是否来自同一标签？</translation>
    </message>
    <message>
        <source>the wall thickness must lie in 0.1..10 mm (%1 given)</source>
        <translation>管壁厚度必须在 0.1..10 mm 之间（给定 %1）</translation>
    </message>
    <message>
        <source>cannot set a DICOM attribute of the report: %1</source>
        <translation>无法设置报告的 DICOM 属性：%1</translation>
    </message>
    <message>
        <source>cannot encapsulate the PDF: %1</source>
        <translation>无法封装 PDF：%1</translation>
    </message>
    <message>
        <source>cannot write the DICOM report: %1</source>
        <translation>无法写入 DICOM 报告：%1</translation>
    </message>
    <message>
        <source>unknown page size &apos;%1&apos;; use a4 or letter</source>
        <translation>未知纸张大小 &apos;%1&apos;；请使用 a4 或 letter</translation>
    </message>
    <message>
        <source>%1: the initial state holds %2</source>
        <translation>%1：初始状态含有 %2</translation>
    </message>
    <message>
        <source>a spring constraint names node %1 of %2</source>
        <translation>弹簧约束指定了 %2 个节点中的节点 %1</translation>
    </message>
    <message>
        <source>element %1 refers to node %2 of %3</source>
        <translation>单元 %1 引用了 %3 个节点中的节点 %2</translation>
    </message>
    <message>
        <source>element %1: %2</source>
        <translation>单元 %1：%2</translation>
    </message>
    <message>
        <source>Young&apos;s modulus must be positive (%1 Pa given)</source>
        <translation>杨氏模量必须为正（给定 %1 Pa）</translation>
    </message>
    <message>
        <source>Poisson&apos;s ratio must lie in (-1, 0.5) (%1 given)</source>
        <translation>泊松比必须在 (-1, 0.5) 内（给定 %1）</translation>
    </message>
    <message>
        <source>the density must be positive (%1 kg/m^3 given)</source>
        <translation>密度必须为正（给定 %1 kg/m^3）</translation>
    </message>
    <message>
        <source>unknown validation case &apos;%1&apos; (known: %2)</source>
        <translation>未知验证算例 &apos;%1&apos;（已知：%2）</translation>
    </message>
    <message>
        <source>St. Venant-Kirchhoff material needs mu &gt; 0 and lambda &gt;= 0 (got mu %1 Pa, lambda %2 Pa)</source>
        <translation>St. Venant-Kirchhoff 材料需要 mu &gt; 0 且 lambda &gt;= 0（得到 mu %1 Pa，lambda %2 Pa）</translation>
    </message>
    <message>
        <source>the quadratic wall model has %1 material indices for %2 elements</source>
        <translation>二次管壁模型有 %1 个材料索引，而单元数为 %2</translation>
    </message>
    <message>
        <source>element %1 has material %2 of %3</source>
        <translation>单元 %1 的材料为 %3 个中的第 %2 个</translation>
    </message>
    <message>
        <source>quadratic element %1 is degenerate or inverted (volume %2 m^3)</source>
        <translation>二次单元 %1 退化或翻转（体积 %2 m^3）</translation>
    </message>
    <message>
        <source>%1 elements are inverted at the start of the static solve%2</source>
        <translation>静态求解开始时有 %1 个单元翻转%2</translation>
    </message>
    <message>
        <source>the saved wall state has %1 nodes, the wall %2</source>
        <translation>保存的管壁状态有 %1 个节点，而管壁有 %2 个</translation>
    </message>
    <message>
        <source>heat-decay: the run at %1 cells stopped: %2</source>
        <translation>heat-decay：%1 个单元的运行已停止：%2</translation>
    </message>
    <message>
        <source>unknown validation case &apos;%1&apos; (known: heat-decay)</source>
        <translation>未知验证算例 &apos;%1&apos;（已知：heat-decay）</translation>
    </message>
    <message>
        <source>outlet node %1 has no boundary condition (a pressure or a terminal resistance)</source>
        <translation>出口节点 %1 没有边界条件（压力或末端阻力）</translation>
    </message>
    <message>
        <source>node %1 takes in flow but no open vessel leaves it</source>
        <translation>节点 %1 有流入，但没有开放血管流出</translation>
    </message>
    <message>
        <source>the inlet segment %1 does not exist (the tree has %2 segments)</source>
        <translation>入口节段 %1 不存在（树有 %2 个节段）</translation>
    </message>
    <message>
        <source>the inlet &apos;%1&apos; is not a point x,y,z (mm)</source>
        <translation>入口 &apos;%1&apos; 不是点 x,y,z（mm）</translation>
    </message>
    <message>
        <source>the inlet point %1 lies %2 mm from the nearest vessel (at most %3 mm)</source>
        <translation>入口点 %1 距最近的血管 %2 mm（最多 %3 mm）</translation>
    </message>
    <message>
        <source>no segment of the tree is named &apos;%1&apos;%2</source>
        <translation>树中没有名为 &apos;%1&apos; 的节段%2</translation>
    </message>
    <message>
        <source>feeder edit: segment %1 is not in the network (%2 segments)</source>
        <translation>供血支编辑：节段 %1 不在网络中（%2 个节段）</translation>
    </message>
    <message>
        <source>feeder edit: segment %1 is both added and removed</source>
        <translation>供血支编辑：节段 %1 同时被添加和移除</translation>
    </message>
    <message>
        <source>end radii are given for %1 of %2 centerline edges</source>
        <translation>只为 %2 条中心线边中的 %1 条给出了端部半径</translation>
    </message>
    <message>
        <source>centerline edge %1 has no positive radius: measure the vessels again</source>
        <translation>中心线边 %1 没有正的半径：请重新测量血管</translation>
    </message>
    <message>
        <source>control point %1 is not on the tree downstream of the tip</source>
        <translation>控制点 %1 不在导管尖端下游的树上</translation>
    </message>
    <message>
        <source>unknown validation case &apos;%1&apos;; network cases: network-cylinder, network-cone, network-conservation, network-bifurcation, network-confluence, network-annulus, network-mixing, network-two-phase-split</source>
        <translation>未知验证算例 &apos;%1&apos;；网络算例：network-cylinder、network-cone、network-conservation、network-bifurcation、network-confluence、network-annulus、network-mixing、network-two-phase-split</translation>
    </message>
    <message>
        <source>the catheter tip is node %1, which is not in the network</source>
        <translation>导管尖端为节点 %1，但它不在网络中</translation>
    </message>
    <message>
        <source>the catheter tip (node %1) is on a part of the network that is not connected to its root</source>
        <translation>导管尖端（节点 %1）位于未与根部相连的网络部分</translation>
    </message>
    <message>
        <source>nothing is downstream of the catheter tip (node %1 is an end of the tree): place it nearer the root (node %2)</source>
        <translation>导管尖端下游没有任何节段（节点 %1 是树的末端）：请将其放得更靠近根部（节点 %2）</translation>
    </message>
    <message>
        <source>the void fraction must be in [0, 1), not %1</source>
        <translation>空隙率必须在 [0, 1) 内，而不是 %1</translation>
    </message>
    <message>
        <source>the catheter tip (node %1) is not connected to the root</source>
        <translation>导管尖端（节点 %1）未与根部相连</translation>
    </message>
    <message>
        <source>a smoke grid needs at least 2 cells along each axis and a positive cell size (got %1 x %2 x %3)</source>
        <translation>烟雾网格每个轴至少需要 2 个单元且单元尺寸为正（得到 %1 x %2 x %3）</translation>
    </message>
    <message>
        <source>smoke-taylor-green: %1</source>
        <translation>smoke-taylor-green：%1</translation>
    </message>
    <message>
        <source>smoke-mass: %1</source>
        <translation>smoke-mass：%1</translation>
    </message>
    <message>
        <source>smoke-ball: %1</source>
        <translation>smoke-ball：%1</translation>
    </message>
    <message>
        <source>unknown validation case &apos;%1&apos; (known: smoke-divergence, smoke-taylor-green, smoke-mass, smoke-ball)</source>
        <translation>未知验证算例 &apos;%1&apos;（已知：smoke-divergence、smoke-taylor-green、smoke-mass、smoke-ball）</translation>
    </message>
    <message>
        <source>%1: the run stopped: %2</source>
        <translation>%1：运行已停止：%2</translation>
    </message>
    <message>
        <source>a periodic axis must be at least 2.5 kernel supports long (%1 mm)</source>
        <translation>周期轴长度至少为 2.5 个核支撑域（%1 mm）</translation>
    </message>
    <message>
        <source>the particles spread over more than %1 neighbour cells</source>
        <translation>粒子分布超过 %1 个邻域单元</translation>
    </message>
    <message>
        <source>the open boundary &apos;%1&apos; needs a unit normal and a positive radius</source>
        <translation>开放边界 &apos;%1&apos; 需要单位法向量和正的半径</translation>
    </message>
    <message>
        <source>a buffer particle names open boundary %1 of %2</source>
        <translation>缓冲粒子指定了 %2 个开放边界中的第 %1 个</translation>
    </message>
    <message>
        <source>the open boundary &apos;%1&apos; has no buffer particles behind it</source>
        <translation>开放边界 &apos;%1&apos; 后方没有缓冲粒子</translation>
    </message>
    <message>
        <source>unknown validation case &apos;%1&apos; (known: sph-kernel, sph-fpm, sph-hydrostatic, sph-poiseuille, sph-womersley, sph-mass, sph-stenosis)</source>
        <translation>未知验证算例 &apos;%1&apos;（已知：sph-kernel、sph-fpm、sph-hydrostatic、sph-poiseuille、sph-womersley、sph-mass、sph-stenosis）</translation>
    </message>
    <message>
        <source>the stenosis pipe needs a mean speed &gt; 0 and room for the sections past the throat (length &gt;= %1 mm)</source>
        <translation>狭窄管需要平均速度 &gt; 0，并为喉部之后的截面留出空间（长度 &gt;= %1 mm）</translation>
    </message>
    <message>
        <source>no section lies %1 mm from both ends of the path to compare with</source>
        <translation>路径上没有距两端均为 %1 mm 的可比较截面</translation>
    </message>
    <message>
        <source>unknown artifact kind &apos;%1&apos;</source>
        <translation>未知工件类型 &apos;%1&apos;</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>cannot replace file: %1</source>
        <translation>无法替换文件：%1</translation>
    </message>
    <message>
        <source>the mask&apos;s grid does not match the image&apos;s (%1): mask %2; image %3</source>
        <translation>掩模网格与图像网格不一致（%1）：掩模 %2；图像 %3</translation>
    </message>
    <message>
        <source>the mask holds the value %1, outside the labels 1..255: give the label value to use (--label-value N)</source>
        <translation>掩模含有值 %1，超出标签范围 1..255：请给出要使用的标签值（--label-value N）</translation>
    </message>
    <message>
        <source>the study was written by a newer VascuSim (schema %1); this build reads schema %2 and older</source>
        <translation>该研究由较新版本的 VascuSim 写入（架构 %1）；本版本可读取架构 %2 及更早版本</translation>
    </message>
    <message>
        <source>segment %1 of the network file: %2</source>
        <translation>网络文件的节段 %1：%2</translation>
    </message>
    <message>
        <source>cannot read the network file: %1</source>
        <translation>无法读取网络文件：%1</translation>
    </message>
    <message>
        <source>the run has no frame %1 (it kept %2)</source>
        <translation>该运行没有帧 %1（它保留了 %2 帧）</translation>
    </message>
    <message>
        <source>artifact &apos;%1&apos; is a %2, not a %3</source>
        <translation>工件 &apos;%1&apos; 是 %2，而不是 %3</translation>
    </message>
    <message>
        <source>artifact &apos;%1&apos; is damaged: %2</source>
        <translation>工件 &apos;%1&apos; 已损坏：%2</translation>
    </message>
    <message>
        <source>artifact &apos;%1&apos; is a %2, not a run</source>
        <translation>工件 &apos;%1&apos; 是 %2，而不是运行</translation>
    </message>
    <message>
        <source>artifact &apos;%1&apos; is not a volume</source>
        <translation>工件 &apos;%1&apos; 不是体积</translation>
    </message>
    <message>
        <source>artifact &apos;%1&apos; was not removed; nothing to restore</source>
        <translation>工件 &apos;%1&apos; 未被移除；无需恢复</translation>
    </message>
    <message>
        <source>cannot open the study&apos;s lock file: %1</source>
        <translation>无法打开研究的锁文件：%1</translation>
    </message>
    <message>
        <source>cannot lock the study: %1</source>
        <translation>无法锁定研究：%1</translation>
    </message>
    <message>
        <source>the study is being written by %1; wait for it (--wait SECONDS) or open the study read-only</source>
        <translation>该研究正由 %1 写入；请等待（--wait SECONDS）或以只读方式打开研究</translation>
    </message>
    <message>
        <source>cannot move the stale lock aside: %1</source>
        <translation>无法移开过期的锁：%1</translation>
    </message>
    <message>
        <source>the surface has no field &apos;%1&apos; to colour by</source>
        <translation>表面没有可用于着色的场 &apos;%1&apos;</translation>
    </message>
    <message>
        <source>the %1 frame has no field &apos;%2&apos; to show in the slices</source>
        <translation>%1 帧没有可在切片中显示的场 &apos;%2&apos;</translation>
    </message>
    <message>
        <source>an element is inverted at rest (negative volume)</source>
        <translation>有单元在静止状态下翻转（体积为负）</translation>
    </message>
    <message>
        <source>an element is degenerate at rest (flat or zero volume)</source>
        <translation>有单元在静止状态下退化（扁平或体积为零）</translation>
    </message>
    <message>
        <source>a tumour grown in its own window holds its darkest part only: give the liver label with --within for the lesion&apos;s boundary against the parenchyma</source>
        <translation>在自身窗口中生长的肿瘤只包含其最暗的部分：请用 --within 给出肝脏标签，以得到病灶与实质的边界</translation>
    </message>
    <message>
        <source>the run ends before the inflow has risen (%1 s): the figures are not of a settled flow</source>
        <translation>运行在入流上升完成（%1 s）之前结束：这些指标不是来自稳定的流动</translation>
    </message>
    <message>
        <source>the averaging starts %1 s after the inflow&apos;s rise, under three settling times (3 x %2 s: the vessel&apos;s resistance x compliance at this sound speed): the figures may not be of a settled flow</source>
        <translation>平均从入流上升后 %1 s 开始，不足三个稳定时间（3 x %2 s：该声速下血管的阻力 x 顺应性）：这些指标可能不是来自稳定的流动</translation>
    </message>
    <message>
        <source>no stenosis figures: %1</source>
        <translation>无狭窄指标：%1</translation>
    </message>
    <message>
        <source>the run stopped before its averaging window (from %1 s): no section averages or stenosis figures</source>
        <translation>运行在平均窗口（自 %1 s 起）之前停止：没有截面平均值或狭窄指标</translation>
    </message>
    <message>
        <source>no liver label in the study (vascusim-cli segment-organ --organ liver): the box phantom was used</source>
        <translation>研究中没有肝脏标签（vascusim-cli segment-organ --organ liver）：已使用长方体体模</translation>
    </message>
    <message>
        <source>ran on the CPU: %1</source>
        <translation>已在 CPU 上运行：%1</translation>
    </message>
    <message>
        <source>stopped early: %1</source>
        <translation>提前停止：%1</translation>
    </message>
    <message>
        <source>the open boundaries let in more particles than the GPU&apos;s arrays hold (%1)</source>
        <translation>开放边界放入的粒子超过了 GPU 数组的容量（%1）</translation>
    </message>
    <message>
        <source>at t = %1 s %2</source>
        <translation>在 t = %1 s 时：%2</translation>
    </message>
    <message>
        <source>particle %1 has a value that is not finite</source>
        <translation>粒子 %1 含有非有限值</translation>
    </message>
    <message>
        <source>particle %1 left the domain (through a wall or an open end without an outlet)</source>
        <translation>粒子 %1 离开了计算域（穿过壁面或没有出口的开放端）</translation>
    </message>
    <message>
        <source>values rescaled to HU by the user&apos;s rescale: HU = %1 x stored + %2</source>
        <translation>已按用户的换算将数值换算为 HU：HU = %1 x 存储值 + %2</translation>
    </message>
    <message>
        <source>%1 voxels clamped to the int16 range</source>
        <translation>%1 个体素被截断到 int16 范围</translation>
    </message>
    <message>
        <source>modality is %1, not CT: values are not Hounsfield units</source>
        <translation>模态为 %1，不是 CT：数值不是亨氏单位</translation>
    </message>
    <message>
        <source>%1 values outside -32768..32767 HU were clamped</source>
        <translation>%1 个超出 -32768..32767 HU 的值已被截断</translation>
    </message>
    <message>
        <source>modality is missing, not CT: values are not Hounsfield units</source>
        <translation>缺少模态，不是 CT：数值不是亨氏单位</translation>
    </message>
    <message>
        <source>%1 localizer image skipped</source>
        <translation>已跳过 %1 幅定位像</translation>
    </message>
    <message>
        <source>%1 localizer images skipped</source>
        <translation>已跳过 %1 幅定位像</translation>
    </message>
    <message>
        <source>series split into %1 sub-series (orientation, image size, pixel spacing, image type or acquisition differ); this is part %2</source>
        <translation>序列已拆分为 %1 个子序列（方向、图像尺寸、像素间距、图像类型或采集不同）；这是第 %2 部分</translation>
    </message>
    <message>
        <source>%1 file is not DICOM (skipped)</source>
        <translation>%1 个文件不是 DICOM（已跳过）</translation>
    </message>
    <message>
        <source>%1 files are not DICOM (skipped)</source>
        <translation>%1 个文件不是 DICOM（已跳过）</translation>
    </message>
    <message>
        <source>%1 DICOM file holds no image (DICOMDIR, reports, ...; skipped)</source>
        <translation>%1 个 DICOM 文件不含图像（DICOMDIR、报告等；已跳过）</translation>
    </message>
    <message>
        <source>%1 DICOM files hold no image (DICOMDIR, reports, ...; skipped)</source>
        <translation>%1 个 DICOM 文件不含图像（DICOMDIR、报告等；已跳过）</translation>
    </message>
    <message>
        <source>%1 DICOM file is damaged or truncated (skipped)</source>
        <translation>%1 个 DICOM 文件已损坏或被截断（已跳过）</translation>
    </message>
    <message>
        <source>%1 DICOM files are damaged or truncated (skipped)</source>
        <translation>%1 个 DICOM 文件已损坏或被截断（已跳过）</translation>
    </message>
    <message>
        <source>%1 voxels belong to several segments: the higher segment number is kept</source>
        <translation>%1 个体素属于多个分割段：保留编号较大的分割段</translation>
    </message>
    <message>
        <source>%1 slices at duplicate positions dropped (kept the lowest instance number)</source>
        <translation>已丢弃位置重复的 %1 个层面（保留实例号最小者）</translation>
    </message>
    <message>
        <source>%1 missing slices (gaps up to %2 mm where the spacing is %3 mm): filled by interpolation</source>
        <translation>缺失 %1 个层面（间隙最大 %2 mm，层间距为 %3 mm）：已通过插值填补</translation>
    </message>
    <message>
        <source>uneven slice spacing (%1 to %2 mm): resampled to %3 mm</source>
        <translation>层间距不均匀（%1 至 %2 mm）：已重采样为 %3 mm</translation>
    </message>
    <message>
        <source>gantry tilt of %1 degrees: resampled onto an orthogonal grid</source>
        <translation>机架倾斜 %1 度：已重采样到正交网格</translation>
    </message>
    <message>
        <source>the series has a single slice</source>
        <translation>该序列只有一个层面</translation>
    </message>
    <message>
        <source>the lowest renal artery was not found in the lumen label: the neck is the narrowest outer diameter within 80 mm above the widest section</source>
        <translation>在管腔标签中未找到最低肾动脉：瘤颈取最宽截面上方 80 mm 内最窄的外径</translation>
    </message>
    <message>
        <source>no sac: the widest outer diameter does not exceed 1.5 x the neck&apos;s</source>
        <translation>无瘤囊：最大外径未超过瘤颈的 1.5 倍</translation>
    </message>
    <message>
        <source>the fronts reached the path-length limit (%1 mm) or a branch limit: the vessel continues beyond the label</source>
        <translation>前沿到达路径长度上限（%1 mm）或分支上限：血管延伸到标签之外</translation>
    </message>
    <message>
        <source>the opening removed every point&apos;s surroundings: the lesion is thinner than the opening there; the label is the grown region without the opening</source>
        <translation>开运算移除了每个点的周围区域：该处病灶比开运算结构更薄；标签为未经开运算的生长区域</translation>
    </message>
    <message>
        <source>the opening removed every point&apos;s surroundings: the organ is thinner than the opening there; the label is the grown region without the opening</source>
        <translation>开运算移除了每个点的周围区域：该处器官比开运算结构更薄；标签为未经开运算的生长区域</translation>
    </message>
    <message>
        <source>weak contrast: blood %1 HU against tissue %2 HU; the boundary may be unreliable</source>
        <translation>对比度弱：血液 %1 HU 对比组织 %2 HU；边界可能不可靠</translation>
    </message>
    <message>
        <source>%1 voxels next to bone or calcium excluded</source>
        <translation>已排除邻近骨骼或钙化的 %1 个体素</translation>
    </message>
    <message>
        <source>%1 boundary faces outside the selection have all their nodes on the lumen surface and carry the pressure too (a wall one element thick there)</source>
        <translation>选区外有 %1 个边界面的所有节点都位于管腔表面上，也承受压力（该处壁厚仅一个单元）</translation>
    </message>
    <message>
        <source>%1 triangles in loose pieces left by the end cuts (or apart from the vessel tree) were dropped</source>
        <translation>已丢弃端部切割留下的（或与血管树分离的）零散碎片中的 %1 个三角形</translation>
    </message>
    <message>
        <source>the lumen surface is open away from the vessel ends (%1 boundary edges; is the segmentation cut by the image border?): those nodes stay free</source>
        <translation>管腔表面在血管端部以外处开放（%1 条边界边；分割是否被图像边界截断？）：这些节点保持自由</translation>
    </message>
    <message>
        <source>%1 elements are inverted where the offset folds (wall thicker than the local radius of curvature): use a thinner wall or a smoother surface</source>
        <translation>%1 个单元在偏移折叠处翻转（壁厚大于局部曲率半径）：请使用更薄的壁或更平滑的表面</translation>
    </message>
    <message>
        <source>end %1 has no open boundary</source>
        <translation>端口 %1 没有开放边界</translation>
    </message>
    <message>
        <source>a value that is not finite: %1</source>
        <translation>非有限值：%1</translation>
    </message>
    <message>
        <source>the run did not reach its end within the step limit of %1 steps (a collapsing time step?)</source>
        <translation>运行未在 %1 步的步数上限内到达终点（时间步长塌缩？）</translation>
    </message>
    <message>
        <source>step %1 left %2</source>
        <translation>第 %1 步留下了%2</translation>
    </message>
    <message>
        <source>the equilibrium at the ramp&apos;s start %1 failed: %2</source>
        <translation>在斜坡起点 %1 处求平衡失败：%2</translation>
    </message>
    <message>
        <source>elements are over the tear strength already at the ramp&apos;s start %1: start lower</source>
        <translation>在斜坡起点 %1 处已有单元超过撕裂强度：请从更低的值开始</translation>
    </message>
    <message>
        <source>no equilibrium in %1 Newton updates (force residual %2)</source>
        <translation>%1 次牛顿更新内未达到平衡（力残差 %2）</translation>
    </message>
    <message>
        <source>the equilibrium at %1 failed: %2</source>
        <translation>在 %1 处求平衡失败：%2</translation>
    </message>
    <message>
        <source>the fracture entropy passed %1 nats at %2</source>
        <translation>在 %2 时断裂熵超过 %1 nats</translation>
    </message>
    <message>
        <source>%1 elements torn at %2</source>
        <translation>在 %2 时 %1 个单元撕裂</translation>
    </message>
    <message>
        <source>the torn wall holds no equilibrium at %1 (rupture): %2</source>
        <translation>撕裂的壁在 %1 时无法保持平衡（破裂）：%2</translation>
    </message>
    <message>
        <source>the equilibrium at %1 % of the pressure did not converge in %2 Newton updates (force residual %3) even in increments of 1/16; the last converged increment is kept</source>
        <translation>在压力的 %1 % 处，即使以 1/16 的增量，平衡也未在 %2 次牛顿更新内收敛（力残差 %3）；保留最后一个收敛的增量</translation>
    </message>
    <message>
        <source>the equilibrium at %1 % of the pressure failed: %2 even in increments of 1/16; the last converged increment is kept</source>
        <translation>在压力的 %1 % 处求平衡失败：%2，即使以 1/16 的增量也是如此；保留最后一个收敛的增量</translation>
    </message>
    <message>
        <source>%1 at step %2 (t = %3 s, pressure %4 MPa); the last good state is kept</source>
        <translation>%1，发生在第 %2 步（t = %3 s，压力 %4 MPa）；保留最后一个有效状态</translation>
    </message>
    <message>
        <source>%1 at step %2; the last good state is kept</source>
        <translation>%1，发生在第 %2 步；保留最后一个有效状态</translation>
    </message>
    <message>
        <source>the fracture entropy reached %1 (end condition %2)</source>
        <translation>断裂熵达到 %1（终止条件 %2）</translation>
    </message>
    <message>
        <source>the equilibrium solve failed (%1); the figures are the load path&apos;s</source>
        <translation>平衡求解失败（%1）；这些指标来自加载路径</translation>
    </message>
    <message>
        <source>%1 elements inverted (the first near %2, %3, %4 mm)</source>
        <translation>%1 个单元翻转（第一个位于 %2, %3, %4 mm 附近）</translation>
    </message>
    <message>
        <source>the solution is no longer finite (NaN or infinity)</source>
        <translation>解不再有限（NaN 或无穷大）</translation>
    </message>
    <message>
        <source>the conjugate gradients broke down (the system is not positive definite)</source>
        <translation>共轭梯度法失效（系统不是正定的）</translation>
    </message>
    <message>
        <source>at t = %1 s the temperature rise at node (%2, %3, %4) reached %5 K, above the initial maximum %6 K: the explicit step is unstable (time step %7 s; the stability limit is h^2/(6D) = %8 s)</source>
        <translation>在 t = %1 s 时，节点 (%2, %3, %4) 的温升达到 %5 K，高于初始最大值 %6 K：显式步长不稳定（时间步长 %7 s；稳定性极限为 h^2/(6D) = %8 s）</translation>
    </message>
    <message>
        <source>the injection (%1 ml/min) is at least the vessel&apos;s own flow at the tip (%2 ml/min)</source>
        <translation>注射速率（%1 ml/min）不低于尖端处血管自身的流量（%2 ml/min）</translation>
    </message>
    <message>
        <source>the catheter fills %1 % of the lumen at the tip</source>
        <translation>导管在尖端处占据管腔的 %1 %</translation>
    </message>
    <message>
        <source>the Reynolds number reaches %1: the flow may not be laminar there, and Hagen-Poiseuille does not hold</source>
        <translation>雷诺数达到 %1：该处流动可能不是层流，哈根-泊肃叶定律不成立</translation>
    </message>
    <message>
        <source>wedged catheter: %1; the injection refluxes or stops the blood flow at the tip</source>
        <translation>导管楔嵌：%1；注射会反流或阻断尖端处的血流</translation>
    </message>
    <message>
        <source>%1 % of the injected drug refluxes past the catheter&apos;s tip (non-target delivery)</source>
        <translation>注入药物的 %1 % 越过导管尖端反流（非靶向递送）</translation>
    </message>
    <message>
        <source>a void fraction of %1 is past bubbly flow (about 0.25): the homogeneous model and the thesis&apos;s experiment do not cover it</source>
        <translation>空隙率 %1 已超出泡状流范围（约 0.25）：均相模型和论文的实验均不涵盖此情况</translation>
    </message>
    <message>
        <source>coverage grade C from this tip: part of a lesion is not perfused (see the feeders)</source>
        <translation>从此尖端的覆盖等级为 C：部分病灶未被灌注（见供血血管）</translation>
    </message>
    <message>
        <source>no outlet of the tree ends inside the tumour: nothing feeds it</source>
        <translation>血管树没有出口终止于肿瘤内：无血管供应它</translation>
    </message>
    <message>
        <source>the flow is no longer finite at t = %1 s</source>
        <translation>在 t = %1 s 时流场不再有限</translation>
    </message>
    <message>
        <source>the flow crossed %1 cells in one step at t = %2 s (the limit is %3): the run is unstable (too strong a confinement or vortex forcing, or too long a step)</source>
        <translation>在 t = %2 s 时流动一步穿越了 %1 个网格（极限为 %3）：运行不稳定（涡量约束或涡粒子强迫过强，或步长过长）</translation>
    </message>
    <message>
        <source>(sorting the particles): %1</source>
        <translation>（粒子排序时）：%1</translation>
    </message>
    <message>
        <source>fluid particle %1 went %2 mm into the wall at %3: the time step or the sound speed is too large for the flow, or the wall thinner than the kernel (a segmentation&apos;s ragged edge: the walls&apos; backstop, parameter wall_repulsion 0.01)</source>
        <translation>流体粒子 %1 在 %3 处进入壁内 %2 mm：时间步长或声速对该流动过大，或壁比核函数更薄（分割的锯齿边缘：壁面的防穿透力，参数 wall_repulsion 0.01）</translation>
    </message>
    <message>
        <source>%1 mm from the wall</source>
        <translation>距壁 %1 mm</translation>
    </message>
    <message>
        <source>particle %1&apos;s density is %2 % from the rest density (guard %3 %) at %4, %5: raise the sound speed or lower the inflow</source>
        <translation>粒子 %1 的密度偏离静止密度 %2 %（保护阈值 %3 %），位于 %4，%5：请提高声速或降低入流</translation>
    </message>
    <message>
        <source>away from the walls</source>
        <translation>远离壁面</translation>
    </message>
    <message>
        <source>the mask was on another grid of the same scan (offset %1, %2, %3 voxels): cut to the image&apos;s grid, every labelled voxel kept</source>
        <translation>掩膜位于同一扫描的另一网格上（偏移 %1, %2, %3 个体素）：已裁剪到图像网格，保留所有标记体素</translation>
    </message>
    <message>
        <source>the mask&apos;s voxels were stored in another axis order or direction: reordered onto the image&apos;s grid, voxel for voxel</source>
        <translation>掩膜的体素以另一种轴顺序或方向存储：已逐体素重排到图像网格</translation>
    </message>
    <message>
        <source>a frame of the run is missing: %1</source>
        <translation>运行缺少一帧：%1</translation>
    </message>
    <message>
        <source>a frame of the run differs from its record (damaged): %1</source>
        <translation>运行的一帧与其记录不符（已损坏）：%1</translation>
    </message>
    <message>
        <source>file is missing: %1</source>
        <translation>文件缺失：%1</translation>
    </message>
    <message>
        <source>file size differs from the manifest: %1</source>
        <translation>文件大小与清单不符：%1</translation>
    </message>
    <message>
        <source>file checksum differs from the manifest (damaged): %1</source>
        <translation>文件校验和与清单不符（已损坏）：%1</translation>
    </message>
    <message>
        <source>artifact &apos;%1&apos; (%2): %3</source>
        <translation>数据项“%1”（%2）：%3</translation>
    </message>
    <message>
        <source>leftover of an interrupted save, removed at the next save: %1</source>
        <translation>中断保存的残留文件，将在下次保存时删除：%1</translation>
    </message>
    <message>
        <source>%1 voxels were not whole numbers and were rounded to integer HU</source>
        <translation>%1 个体素不是整数，已四舍五入为整数 HU</translation>
    </message>
    <message>
        <source>%1 voxels were outside the int16 range or not finite and were clamped</source>
        <translation>%1 个体素超出 int16 范围或非有限值，已被截断</translation>
    </message>
    <message>
        <source>clamped 0.5 x 0.1 x 0.1 m beam (70 x 14 x 14 cells, %1 tets, E = 1 MPa, nu = 0) with a tip load: mean tip deflection against Timoshenko theory P L^3 / (3 E I) + P L / (k G A), k = 10 (1 + nu) / (12 + 11 nu)</source>
        <translation>一端固支的 0.5 x 0.1 x 0.1 m 梁（70 x 14 x 14 个网格，%1 个四面体，E = 1 MPa，nu = 0）受端部载荷：平均端部挠度与 Timoshenko 理论 P L^3 / (3 E I) + P L / (k G A)，k = 10 (1 + nu) / (12 + 11 nu) 对比</translation>
    </message>
    <message>
        <source>quarter of a thick-walled tube (a = 10 mm, b = 20 mm, %1 tets, E = 1 MPa, nu = 0.45) under 1 kPa inside, plane strain and symmetry planes: radial displacement and hoop stress against Lame&apos;s solution</source>
        <translation>厚壁管的四分之一（a = 10 mm，b = 20 mm，%1 个四面体，E = 1 MPa，nu = 0.45），内压 1 kPa，平面应变和对称面：径向位移和环向应力与 Lamé 解对比</translation>
    </message>
    <message>
        <source>quarter of a thick-walled tube (a = 10 mm, b = 20 mm, %1 quadratic tets, E = 1 MPa, nu = 0.49, nearly incompressible) under 1 kPa inside (follower), plane strain and symmetry planes, Newton to 1e-8: radial displacement and the elements&apos; hoop stress (mean of the 4 quadrature points, no averaging over cells) against Lame&apos;s solution</source>
        <translation>厚壁管的四分之一（a = 10 mm，b = 20 mm，%1 个二次四面体，E = 1 MPa，nu = 0.49，近不可压缩），内压 1 kPa（随动），平面应变和对称面，牛顿迭代至 1e-8：径向位移和单元环向应力（4 个积分点的平均，不跨单元平均）与 Lamé 解对比</translation>
    </message>
    <message>
        <source>constant-strain patch: boundary nodes of a 4x4x4-cell cube (384 tets) moved by u = A X + c, interior solved; interior displacement and element stress against the exact linear field</source>
        <translation>常应变分片试验：4x4x4 网格立方体（384 个四面体）的边界节点按 u = A X + c 移动，求解内部；内部位移和单元应力与精确线性场对比</translation>
    </message>
    <message>
        <source>a 0.1 x 0.05 x 0.05 m block (96 tets, E = 1 MPa) turned 90 degrees about z and moved: largest elastic force against E h^2 (h = element size)</source>
        <translation>一个 0.1 x 0.05 x 0.05 m 的块（96 个四面体，E = 1 MPa）绕 z 轴旋转 90 度并平移：最大弹性力与 E h^2（h = 单元尺寸）对比</translation>
    </message>
    <message>
        <source>a 0.2 m cantilever (240 tets) bent by a tip load, released without load; backward Euler, h = 1 ms, 300 steps, Rayleigh beta = 0.22 s (thesis) and 0.005 s: total energy (kinetic + elastic) must never rise</source>
        <translation>一根 0.2 m 悬臂梁（240 个四面体）受端部载荷弯曲后无载释放；后向欧拉法，h = 1 ms，300 步，Rayleigh beta = 0.22 s（论文）和 0.005 s：总能量（动能 + 弹性能）不得上升</translation>
    </message>
    <message>
        <source>the slowest mode of a 20 mm cube of tissue (D 0.14 mm^2/s) after one decay time, on the run driver: relative L2 error against the exact solution, and its order of convergence</source>
        <translation>20 mm 组织立方体（D 0.14 mm^2/s）最慢模态经过一个衰减时间后（在运行驱动器上）：相对于精确解的相对 L2 误差及其收敛阶</translation>
    </message>
    <message>
        <source>conical resistance with R1 = R2 against 8 mu L / (pi R^4)</source>
        <translation>R1 = R2 时的锥形阻力与 8 mu L / (pi R^4) 对比</translation>
    </message>
    <message>
        <source>eq. 6.6 against eq. 6.4 integrated (Gauss-Legendre, 64 x 8 points)</source>
        <translation>式 6.6 与积分后的式 6.4 对比（Gauss-Legendre，64 x 8 个点）</translation>
    </message>
    <message>
        <source>Kirchhoff&apos;s law on a seeded random tree of 2,000 segments</source>
        <translation>在含 2,000 个段的固定种子随机树上验证基尔霍夫定律</translation>
    </message>
    <message>
        <source>tip -&gt; junction -&gt; two branches with terminal resistances into 1,000 and 2,000 Pa</source>
        <translation>尖端 -&gt; 分叉 -&gt; 两个分支，末端阻力分别通向 1,000 和 2,000 Pa</translation>
    </message>
    <message>
        <source>injected branch and a second inlet at 6,000 Pa joining before one outlet at 500 Pa</source>
        <translation>注射分支与 6,000 Pa 的第二入口在 500 Pa 的单一出口前汇合</translation>
    </message>
    <message>
        <source>a catheter in a pipe: the annulus&apos;s Hagen-Poiseuille resistance</source>
        <translation>管中的导管：环形间隙的哈根-泊肃叶阻力</translation>
    </message>
    <message>
        <source>blood from the root and an injection at a tip, mixed at a confluence with a second inlet</source>
        <translation>来自根部的血液与尖端处的注射，在与第二入口的汇合处混合</translation>
    </message>
    <message>
        <source>the injected mixture&apos;s viscosity shifts the split between the tip&apos;s branch and its sibling</source>
        <translation>注入混合物的黏度改变尖端分支与其兄弟分支之间的分流</translation>
    </message>
    <message>
        <source>a puff of smoke (1e-3 kg/m^3, 30 K above the ambient, 0.15 m radius) rising by buoyancy in a closed 1 m box of 32^3 cells, 500 steps (the velocity by MacCormack with the limiter): the smoke mass at the end against the start, without renormalisation, moved by the limited finite-volume transport; moved by semi-Lagrangian MacCormack instead it drifted by %1 %</source>
        <translation>一团烟雾（1e-3 kg/m^3，高于环境 30 K，半径 0.15 m）在 32^3 网格的封闭 1 m 箱内因浮力上升，500 步（速度采用带限制器的 MacCormack）：由限制的有限体积输运移动、不做重归一化时，结束时与开始时的烟雾质量对比；若改用半拉格朗日 MacCormack 移动，则漂移 %1 %</translation>
    </message>
    <message>
        <source>a random velocity field (uniform in +-1 m/s on the faces) in a 1 m box of 48^3 cells, walls with an open top and a solid sphere of 0.15 m radius at the centre, projected by MGPCG to a relative residual of 1e-6 on three seeds: the largest |div u| h / max |u| left</source>
        <translation>一个随机速度场（面上在 +-1 m/s 内均匀分布），位于 48^3 网格的 1 m 箱内，顶部开放的壁面，中心有半径 0.15 m 的固体球，用 MGPCG 投影到相对残差 1e-6，三个种子：剩余的最大 |div u| h / max |u|</translation>
    </message>
    <message>
        <source>the inviscid Taylor-Green vortex u = (sin x cos y cos z, -cos x sin y cos z, 0) (pi/m, 1 m/s) in a 1 m free-slip box of 32^3 cells for 1 s: the effective numerical viscosity -(dE/dt) / integral |w|^2 with vorticity confinement (epsilon 0.5) and with vortex particles (epsilon 0.5, r = 2 h) against the plain semi-Lagrangian scheme</source>
        <translation>无黏 Taylor-Green 涡 u = (sin x cos y cos z, -cos x sin y cos z, 0)（pi/m，1 m/s），在 32^3 网格的 1 m 自由滑移箱内运行 1 s：带涡量约束（epsilon 0.5）和带涡粒子（epsilon 0.5，r = 2 h）时的有效数值黏度 -(dE/dt) / 积分 |w|^2，与普通半拉格朗日格式对比</translation>
    </message>
    <message>
        <source>a ball of 0.1 m radius dropped from rest at 0.75 m in still air (a 1 m box of 48^3 cells, open at the top), falling under gravity for 0.25 s: the flow through the ball (the faces it touches against its own velocity), the divergence left around it, and the air pushed aside</source>
        <translation>半径 0.1 m 的球从 0.75 m 高处在静止空气中由静止释放（顶部开放、48^3 网格的 1 m 箱），在重力下下落 0.25 s：穿过球体的流动（其接触的面与其自身速度对比）、其周围剩余的散度，以及被推开的空气</translation>
    </message>
    <message>
        <source>water at rest in an open tank (8 x 8 x 16 particles of 1 mm, 4 wall layers) after 0.3 s under gravity, and the same tank of mixture particles at void fraction 0.2 (thesis Table 5.1): the pressure in the middle of the column, 2h below the surface and deeper, against the hydrostatic pressure of the model&apos;s fluid</source>
        <translation>开放水箱中的静止水（8 x 8 x 16 个 1 mm 粒子，4 层壁）在重力下 0.3 s 后，以及空隙率 0.2 的混合粒子的同一水箱（论文表 5.1）：液柱中部、表面以下 2h 及更深处的压力与模型流体的静水压力对比</translation>
    </message>
    <message>
        <source>%1 (%2 particles evaluated)</source>
        <translation>%1（评估了 %2 个粒子）</translation>
    </message>
    <message>
        <source>the 3D quartic kernel (h = 2 mm): its integral, W(2h), dW/dr against a central difference, and its first moment on a 1 mm particle lattice against the identity</source>
        <translation>三维四次核函数（h = 2 mm）：其积分、W(2h)、dW/dr 与中心差分对比，以及其在 1 mm 粒子晶格上的一阶矩与单位矩阵对比</translation>
    </message>
    <message>
        <source>the gradient of a linear field at jittered particles (1 mm, +-0.2 mm) within h of a wall, three seeds: the first-order Finite Particle Method against the exact gradient, and plain SPH&apos;s error beside it</source>
        <translation>在距壁 h 以内的扰动粒子（1 mm，+-0.2 mm）上线性场的梯度，三个种子：一阶有限粒子法与精确梯度对比，并列出普通 SPH 的误差</translation>
    </message>
    <message>
        <source>pipe 1 mm across, 2 mm long, velocity inlet (parabolic, mean 0.05 m/s, tracer) and pressure outlet, tracer absorbed within 0.1 mm of the wall, 6 ms: inflow %1 ug, outflow %2 ug, absorbed %3 ug, mass change %4 ug (%5 steps)</source>
        <translation>直径 1 mm、长 2 mm 的管，速度入口（抛物线型，平均 0.05 m/s，示踪剂）和压力出口，示踪剂在距壁 0.1 mm 内被吸收，6 ms：流入 %1 ug，流出 %2 ug，吸收 %3 ug，质量变化 %4 ug（%5 步）</translation>
    </message>
    <message>
        <source>plane Poiseuille flow, 20 particles across a 2 mm channel (periodic along and across the flow, peak 0.1 m/s, Re 2), after 7 decay times: every fluid particle&apos;s velocity against the steady profile</source>
        <translation>平面泊肃叶流，2 mm 通道内横跨 20 个粒子（沿流向和横向周期，峰值 0.1 m/s，Re 2），经过 7 个衰减时间后：每个流体粒子的速度与稳态剖面对比</translation>
    </message>
    <message>
        <source>50 % diameter cosine stenosis in a 1.6 mm pipe, 0.05 m/s mean inflow (Re 48 in the throat), averaged 15-25 ms: peak velocity ratio %1 upstream (%2 -&gt; %3 m/s), %4 downstream</source>
        <translation>1.6 mm 管中直径 50 % 的余弦狭窄，平均入流 0.05 m/s（狭窄喉部 Re 48），在 15-25 ms 内平均：上游峰值流速比 %1（%2 -&gt; %3 m/s），下游 %4</translation>
    </message>
    <message>
        <source>mean ratio %1 (area ratio %2); pressure drop %3 Pa over 3.2 mm; throat wall shear stress %4 Pa (TAWSS); %5 steps, %6 particles</source>
        <translation>平均比 %1（面积比 %2）；3.2 mm 上的压降 %3 Pa；喉部壁面剪应力 %4 Pa（TAWSS）；%5 步，%6 个粒子</translation>
    </message>
    <message>
        <source>pulsatile flow in a rigid pipe 20 particles across (0.1 mm, periodic along its axis) from rest, alpha 4 (four cycles) and 8 (three): the velocity next to the axis over the last cycle against Womersley&apos;s solution</source>
        <translation>刚性管中的脉动流，横跨 20 个粒子（0.1 mm，沿轴向周期），从静止开始，alpha 4（四个周期）和 8（三个周期）：最后一个周期内轴线附近的速度与 Womersley 解对比</translation>
    </message>
    <message>
        <source>Vessel lumen</source>
        <translation>血管管腔</translation>
    </message>
    <message>
        <source>Lumen surface</source>
        <translation>管腔表面</translation>
    </message>
    <message>
        <source>Vessel skeleton</source>
        <translation>血管骨架</translation>
    </message>
    <message>
        <source>Centerlines</source>
        <translation>中心线</translation>
    </message>
    <message>
        <source>Imported label</source>
        <translation>导入的标签</translation>
    </message>
    <message>
        <source>%1 (grown from one point)</source>
        <translation>%1（从一个点生长）</translation>
    </message>
    <message>
        <source>%1 (grown from %2 points)</source>
        <translation>%1（从 %2 个点生长）</translation>
    </message>
    <message>
        <source>Cloth sheet</source>
        <translation>布片</translation>
    </message>
    <message>
        <source>Imported wall</source>
        <translation>导入的管壁</translation>
    </message>
    <message>
        <source>Blood flow (SPH)</source>
        <translation>血流（SPH）</translation>
    </message>
    <message>
        <source>Wall loads (SPH)</source>
        <translation>管壁载荷（SPH）</translation>
    </message>
    <message>
        <source>DICOM series %1</source>
        <translation>DICOM 序列 %1</translation>
    </message>
    <message>
        <source>Vessel lumen (aorta)</source>
        <translation>血管管腔（主动脉）</translation>
    </message>
    <message>
        <source>Vessel lumen (hepatic arteries)</source>
        <translation>血管管腔（肝动脉）</translation>
    </message>
    <message>
        <source>Vessel lumen (from points)</source>
        <translation>血管管腔（来自点）</translation>
    </message>
    <message>
        <source>Needle injection (SPH)</source>
        <translation>针头注射（SPH）</translation>
    </message>
    <message>
        <source>Drug filling</source>
        <translation>药物充盈</translation>
    </message>
    <message>
        <source>Drug flow</source>
        <translation>药物流动</translation>
    </message>
    <message>
        <source>AAA sac (lumen 1, thrombus 4, wall 5)</source>
        <translation>AAA 瘤囊（管腔 1，血栓 4，管壁 5）</translation>
    </message>
    <message>
        <source>Surgical smoke (%1, illustrative)</source>
        <translation>手术烟雾（%1，示意性）</translation>
    </message>
    <message>
        <source>Report (anonymized)</source>
        <translation>报告（已匿名化）</translation>
    </message>
    <message>
        <source>Report</source>
        <translation>报告</translation>
    </message>
    <message>
        <source>Wall run (%1)</source>
        <translation>管壁运行（%1）</translation>
    </message>
    <message>
        <source>Wall stress (%1)</source>
        <translation>管壁应力（%1）</translation>
    </message>
    <message>
        <source>Vessel wall</source>
        <translation>血管壁</translation>
    </message>
    <message>
        <source>Ruler %1: %2</source>
        <translation>标尺 %1：%2</translation>
    </message>
    <message>
        <source>Angle %1: %2</source>
        <translation>角度 %1：%2</translation>
    </message>
    <message>
        <source>ROI %1: %2</source>
        <translation>ROI %1：%2</translation>
    </message>
    <message>
        <source>mean %1 HU, SD %2 HU, area %3 mm2</source>
        <translation>平均 %1 HU，标准差 %2 HU，面积 %3 mm2</translation>
    </message>
    <message>
        <source>physiological</source>
        <translation>生理</translation>
    </message>
    <message>
        <source>thesis-rupture</source>
        <translation>论文破裂</translation>
    </message>
    <message>
        <source>interactive</source>
        <translation>交互</translation>
    </message>
    <message>
        <source>tumour</source>
        <translation>肿瘤</translation>
    </message>
    <message>
        <source>liver</source>
        <translation>肝脏</translation>
    </message>
    <message>
        <source>ball drop</source>
        <translation>落球</translation>
    </message>
    <message>
        <source>endoscopic vessel harvesting</source>
        <translation>内镜下血管采集</translation>
    </message>
    <message>
        <source>liver ablation</source>
        <translation>肝脏消融</translation>
    </message>
    <message>
        <source>unnamed (nodes %1-%2)</source>
        <translation>未命名（节点 %1-%2）</translation>
    </message>
    <message>
        <source>%1 at %2:%3 (TLS)</source>
        <translation>%1，位于 %2:%3（TLS）</translation>
    </message>
    <message>
        <source>%1 at %2:%3</source>
        <translation>%1，位于 %2:%3</translation>
    </message>
    <message>
        <source>aorta</source>
        <translation>主动脉</translation>
    </message>
    <message>
        <source>left common iliac artery</source>
        <translation>左髂总动脉</translation>
    </message>
    <message>
        <source>right common iliac artery</source>
        <translation>右髂总动脉</translation>
    </message>
    <message>
        <source>left renal artery</source>
        <translation>左肾动脉</translation>
    </message>
    <message>
        <source>right renal artery</source>
        <translation>右肾动脉</translation>
    </message>
    <message>
        <source>superior mesenteric artery</source>
        <translation>肠系膜上动脉</translation>
    </message>
    <message>
        <source>celiac trunk</source>
        <translation>腹腔干</translation>
    </message>
    <message>
        <source>splenic artery</source>
        <translation>脾动脉</translation>
    </message>
    <message>
        <source>common hepatic artery</source>
        <translation>肝总动脉</translation>
    </message>
    <message>
        <source>gastroduodenal artery</source>
        <translation>胃十二指肠动脉</translation>
    </message>
    <message>
        <source>proper hepatic artery</source>
        <translation>肝固有动脉</translation>
    </message>
    <message>
        <source>right hepatic artery</source>
        <translation>肝右动脉</translation>
    </message>
    <message>
        <source>left hepatic artery</source>
        <translation>肝左动脉</translation>
    </message>
    <message>
        <source>segmental hepatic artery</source>
        <translation>肝段动脉</translation>
    </message>
    <message>
        <source>this model does not solve its own tangent</source>
        <translation>此模型不自行求解其切线刚度</translation>
    </message>
    <message>
        <source>a model that solves its own tangent (the GPU) takes the conjugate-gradient static solve</source>
        <translation>自行求解切线刚度的模型（GPU）须使用共轭梯度静力求解</translation>
    </message>
    <message>
        <source>the multigrid preconditioner needs the model&apos;s positions</source>
        <translation>多重网格预条件器需要模型的位置</translation>
    </message>
    <message>
        <source>the static solve on the GPU is the modified Newton iteration with multigrid conjugate gradients</source>
        <translation>GPU 上的静力求解是采用多重网格共轭梯度的修正牛顿迭代</translation>
    </message>
    <message>
        <source>the static wall on the GPU was made for another mesh</source>
        <translation>GPU 上的静力管壁是为另一网格建立的</translation>
    </message>
    <message>
        <source>the mask holds one value (%1): stored as label 1, the lumen&apos;s (give --label-value N for another)</source>
        <translation>掩膜只含一个值（%1）：已存为标签 1，即管腔的标签（如需其他值请给出 --label-value N）</translation>
    </message>
    <message>
        <source>particle shifting (particle_shifting &gt; 0) needs a fluid that fills its vessel: a free surface (free_surface 1) or a fluid without tension (fluid_tension 0) would be pushed apart at its edge; set particle_shifting 0</source>
        <translation>粒子位移（particle_shifting &gt; 0）需要充满其血管的流体：自由表面（free_surface 1）或无张力流体（fluid_tension 0）会在边缘被推开；请设置 particle_shifting 0</translation>
    </message>
    <message>
        <source>the saved section averages are for %1 sections, this run has %2</source>
        <translation>保存的截面平均值对应 %1 个截面，本次运行有 %2 个</translation>
    </message>
    <message>
        <source>the saved run has %1 open boundaries, this run %2: the checkpoint belongs to another problem</source>
        <translation>保存的运行有 %1 个开放边界，本次运行有 %2 个：该检查点属于另一个问题</translation>
    </message>
    <message>
        <source>the SPH checkpoint is cut short or damaged</source>
        <translation>SPH 检查点不完整或已损坏</translation>
    </message>
    <message>
        <source>will not replace a file that is not an SPH checkpoint</source>
        <translation>不会替换非 SPH 检查点的文件</translation>
    </message>
    <message>
        <source>cannot write the SPH checkpoint</source>
        <translation>无法写入 SPH 检查点</translation>
    </message>
    <message>
        <source>cannot open the SPH checkpoint</source>
        <translation>无法打开 SPH 检查点</translation>
    </message>
    <message>
        <source>not an SPH checkpoint of this version (its first line is not &apos;VSIM-SPH-CHECKPOINT 2&apos;)</source>
        <translation>不是此版本的 SPH 检查点（其第一行不是 &apos;VSIM-SPH-CHECKPOINT 2&apos;）</translation>
    </message>
    <message>
        <source>the saved run&apos;s wall particle %1 is not this run&apos;s: the checkpoint belongs to another problem</source>
        <translation>保存的运行中的壁面粒子 %1 不属于本次运行：该检查点属于另一个问题</translation>
    </message>
    <message>
        <source>the saved run has %1 wall particles, this run %2: the checkpoint belongs to another problem</source>
        <translation>保存的运行有 %1 个壁面粒子，本次运行有 %2 个：该检查点属于另一个问题</translation>
    </message>
    <message>
        <source>the saved wall-load averages are for %1 points, this run has %2</source>
        <translation>保存的壁面载荷平均值对应 %1 个点，本次运行有 %2 个</translation>
    </message>
    <message>
        <source>the saved rates do not fit the particles: the checkpoint is damaged</source>
        <translation>保存的速率与粒子不符：检查点已损坏</translation>
    </message>
    <message>
        <source>the saved run shifted its particles and this run does not (particle_shifting 0): the checkpoint belongs to another problem</source>
        <translation>保存的运行对粒子做了位移，而本次运行没有（particle_shifting 0）：该检查点属于另一个问题</translation>
    </message>
    <message>
        <source>this run shifts its particles (particle_shifting) and the saved run did not: the checkpoint belongs to another problem</source>
        <translation>本次运行对粒子做位移（particle_shifting），而保存的运行没有：该检查点属于另一个问题</translation>
    </message>
    <message>
        <source>the dam break experiment&apos;s record does not cover that time</source>
        <translation>溃坝实验的记录不包含该时刻</translation>
    </message>
    <message>
        <source>sph-dambreak needs a GPU at its million particles (about 20 hours on 2 CPU cores): %1; validate sph-dambreak --backend cpu [--particles N] runs it on the CPU</source>
        <translation>sph-dambreak 在其一百万粒子规模下需要 GPU（在 2 个 CPU 核上约需 20 小时）：%1；validate sph-dambreak --backend cpu [--particles N] 可在 CPU 上运行</translation>
    </message>
    <message>
        <source>the dam break&apos;s end must lie within the experiment&apos;s record (0 to %1 s)</source>
        <translation>溃坝的结束时间必须在实验记录范围内（0 至 %1 s）</translation>
    </message>
    <message>
        <source>SPHERIC benchmark 2 (Kleefsman et al. 2005): the dam break with the obstacle, %1 particles (%2 walls) at %3 mm, c0 %4 m/s, on the %5; the water heights at the probes H1-H4 every 20 ms against MARIN&apos;s record (this project&apos;s tolerance: RMS within 10 % of the 0.55 m column, fronts within 50 ms, the whole record run)%6</source>
        <translation>SPHERIC 基准 2（Kleefsman 等，2005）：带障碍物的溃坝，%1 个粒子（%2 个壁面粒子），间距 %3 mm，c0 %4 m/s，在 %5 上；探针 H1-H4 处每 20 ms 的水位与 MARIN 的记录比较（本项目的容差：RMS 在 0.55 m 水柱的 10 % 以内，波前到达在 50 ms 以内，须运行完整记录）%6</translation>
    </message>
    <message>
        <source>; stopped by a guard: %1</source>
        <translation>；被保护条件停止：%1</translation>
    </message>
    <message>
        <source>dam break</source>
        <translation>溃坝</translation>
    </message>
    <message>
        <source>GPU (single precision)</source>
        <translation>GPU（单精度）</translation>
    </message>
    <message>
        <source>CPU (double precision)</source>
        <translation>CPU（双精度）</translation>
    </message>
    <message>
        <source>a pulsatile inflow needs a period &gt; 0 s and an amplitude in [0, 1), not %1 s and %2</source>
        <translation>脉动入流需要周期 &gt; 0 s 且振幅在 [0, 1) 内，而不是 %1 s 和 %2</translation>
    </message>
    <message>
        <source>the SPH input gives some of the particles&apos; velocity components, not all three: give velocity_x_m_s, velocity_y_m_s and velocity_z_m_s together</source>
        <translation>SPH 输入只给出了粒子速度的部分分量，而不是全部三个：请同时给出 velocity_x_m_s、velocity_y_m_s 和 velocity_z_m_s</translation>
    </message>
    <message>
        <source>the open boundary &apos;%1&apos; has buffer particles down to %2 mm behind its plane, and its buffer must be as deep as the kernel&apos;s support, %3 mm (2 x the smoothing ratio x the spacing): seed it for this smoothing ratio</source>
        <translation>开放边界 &apos;%1&apos; 的缓冲粒子位于其平面后方至 %2 mm 处，而其缓冲区必须与核函数的支撑域一样深，即 %3 mm（2 x 光滑比 x 粒子间距）：请按此光滑比重新布置粒子</translation>
    </message>
    <message>
        <source>density by summation (density_summation 1) needs a fluid that fills its vessel: at a free surface (free_surface 1) or the edge of a liquid without tension (fluid_tension 0) the particles&apos; sums fall short and would read as suction; set density_summation 0</source>
        <translation>求和密度（density_summation 1）需要充满血管的流体：在自由表面（free_surface 1）或无张力液体（fluid_tension 0）的边缘，粒子的求和不足，会被读作吸力；请设置 density_summation 0</translation>
    </message>
    <message>
        <source>the Finite Particle Method (fpm 1) corrects the continuity equation&apos;s density rate, which density by summation (density_summation 1) does not use: set one of them to 0</source>
        <translation>有限粒子法（fpm 1）修正连续性方程的密度变化率，而求和密度（density_summation 1）不使用它：请将其中之一设为 0</translation>
    </message>
    <message>
        <source>the density&apos;s relaxation towards summation (density_relaxation_s &gt; 0) is for the continuity density (density_summation 0) of a fluid that fills its vessel (free_surface 0, fluid_tension 1): set density_relaxation_s 0</source>
        <translation>密度向求和密度的松弛（density_relaxation_s &gt; 0）适用于充满血管的流体（free_surface 0，fluid_tension 1）的连续性密度（density_summation 0）：请设置 density_relaxation_s 0</translation>
    </message>
    <message>
        <source>at t = %1 s the vessel has lost %2 % of its first fluid mass through its open ends (outflow - inflow; fluid_loss_guard %3 %): its particles no longer fill it, so its figures would not be a flow&apos;s; relax the density towards summation (density_relaxation_s) or raise the sound speed</source>
        <translation>在 t = %1 s 时，血管已通过其开放端失去其初始流体质量的 %2 %（流出 - 流入；fluid_loss_guard %3 %）：其粒子已不再充满血管，因此其数值不代表流动；请使密度向求和密度松弛（density_relaxation_s）或提高声速</translation>
    </message>
    <message>
        <source>the SPH input&apos;s particles carry the field &apos;%1&apos;, which the solver does not read (it reads wall, wall_depth_mm, open_boundary, tracer, pressure_pa, velocity_x_m_s, velocity_y_m_s, velocity_z_m_s and void_fraction): is it misspelt?</source>
        <translation>SPH 输入的粒子带有字段 &apos;%1&apos;，求解器不读取该字段（它读取 wall、wall_depth_mm、open_boundary、tracer、pressure_pa、velocity_x_m_s、velocity_y_m_s、velocity_z_m_s 和 void_fraction）：是否拼写错误？</translation>
    </message>
    <message>
        <source>the wall loads %1 have no wall_pressure_pa</source>
        <translation>壁面载荷 %1 没有 wall_pressure_pa</translation>
    </message>
    <message>
        <source>none of the wall&apos;s %1 lumen points lies within %2 mm of the blood flow&apos;s wall (%3): the flow ran through other vessels</source>
        <translation>血管壁的 %1 个管腔点中没有一个位于血流壁面 (%3) 的 %2 mm 以内：血流经过的是其他血管</translation>
    </message>
    <message>
        <source>flow_wall_pressure 1 needs a blood-flow run&apos;s wall loads in the study (Flow &gt; Blood Flow, or vascusim-cli simulate sph, run to its averaging window)</source>
        <translation>flow_wall_pressure 1 需要研究中某次血流计算的壁面载荷（血流 &gt; 血流 (SPH)，或 vascusim-cli simulate sph，并运行到其平均时间窗）</translation>
    </message>
    <message>
        <source>the wall mesh has no wall_layer field: its lumen is not known</source>
        <translation>血管壁网格没有 wall_layer 字段：其管腔未知</translation>
    </message>
    <message>
        <source>the blood flow&apos;s wall pressure reached %1 % of the lumen; the rest carries the uniform pressure</source>
        <translation>血流的壁面压力覆盖了 %1 % 的管腔；其余部分承受均匀压力</translation>
    </message>
    <message>
        <source>flow_wall_pressure 1 needs the blood flow&apos;s wall pressure on the wall&apos;s lumen (vascusim-cli simulate fem or the workstation add it from the study&apos;s newest blood-flow run)</source>
        <translation>flow_wall_pressure 1 需要血管壁管腔上的血流壁面压力（vascusim-cli simulate fem 或工作站会从研究中最新的血流计算添加）</translation>
    </message>
    <message>
        <source>flow_wall_pressure 1 needs wall_model 1 (the quadratic hyperelastic wall)</source>
        <translation>flow_wall_pressure 1 需要 wall_model 1（二次超弹性血管壁）</translation>
    </message>
    <message>
        <source>the lumen&apos;s added pressure (%1) must be finite and leave the pressure positive (%2 Pa + %3 Pa)</source>
        <translation>管腔的附加压力 (%1) 必须是有限值且使压力保持为正 (%2 Pa + %3 Pa)</translation>
    </message>
    <message>
        <source>%1 face pressures for %2 pressure faces</source>
        <translation>%1 个面压力对应 %2 个受压面</translation>
    </message>
</context>
<context>
    <name>vsim::Parameters</name>
    <message>
        <source>Layer 1: window and region growing</source>
        <translation>第 1 层：窗口与区域生长</translation>
    </message>
    <message>
        <source>Lowest contrast HU</source>
        <translation>最低对比 HU</translation>
    </message>
    <message>
        <source>Lowest HU of contrast-filled blood; kidneys and tumour blush (about 150 HU) stay below.</source>
        <translation>充盈造影剂血液的最低 HU；肾脏和肿瘤染色（约 150 HU）低于此值。</translation>
    </message>
    <message>
        <source>Highest contrast HU</source>
        <translation>最高对比 HU</translation>
    </message>
    <message>
        <source>Highest HU of contrast-filled blood; bone and calcium above it are excluded.</source>
        <translation>充盈造影剂血液的最高 HU；高于此值的骨骼和钙化被排除。</translation>
    </message>
    <message>
        <source>Denoising sigma</source>
        <translation>去噪 sigma</translation>
    </message>
    <message>
        <source>Recursive Gaussian applied before thresholding (noise and partial volume).</source>
        <translation>阈值化之前施加的递归高斯滤波（噪声与部分容积）。</translation>
    </message>
    <message>
        <source>Boundary level</source>
        <translation>边界水平</translation>
    </message>
    <message>
        <source>Boundary HU = tissue + fraction x (blood - tissue); 0.5 is the partial-volume half level.</source>
        <translation>边界 HU = 组织 + 比例 x（血液 - 组织）；0.5 为部分容积的半高水平。</translation>
    </message>
    <message>
        <source>Automatic seed erosion</source>
        <translation>自动种子腐蚀</translation>
    </message>
    <message>
        <source>The automatic seed lies in the largest bright component left after eroding this much (thick tubes).</source>
        <translation>自动种子位于腐蚀此量后剩余的最大亮连通区内（粗管）。</translation>
    </message>
    <message>
        <source>Region margin</source>
        <translation>区域边距</translation>
    </message>
    <message>
        <source>Margin around the vessels found coarsely, inside which the fine layers work.</source>
        <translation>粗略找到的血管周围的边距，精细层在其中工作。</translation>
    </message>
    <message>
        <source>Layer 2: vesselness</source>
        <translation>第 2 层：血管性</translation>
    </message>
    <message>
        <source>Vesselness threshold</source>
        <translation>血管性阈值</translation>
    </message>
    <message>
        <source>Relative Frangi vesselness above which thin branches are added (0 turns layer 2 off).</source>
        <translation>相对 Frangi 血管性，高于此值时加入细分支（0 关闭第 2 层）。</translation>
    </message>
    <message>
        <source>Smallest vessel scale</source>
        <translation>最小血管尺度</translation>
    </message>
    <message>
        <source>Smallest Hessian scale.</source>
        <translation>最小 Hessian 尺度。</translation>
    </message>
    <message>
        <source>Largest vessel scale</source>
        <translation>最大血管尺度</translation>
    </message>
    <message>
        <source>Largest Hessian scale.</source>
        <translation>最大 Hessian 尺度。</translation>
    </message>
    <message>
        <source>Vesselness scales</source>
        <translation>血管性尺度数</translation>
    </message>
    <message>
        <source>Number of Hessian scales.</source>
        <translation>Hessian 尺度的数量。</translation>
    </message>
    <message>
        <source>Layer 3: level set</source>
        <translation>第 3 层：水平集</translation>
    </message>
    <message>
        <source>Level-set steps</source>
        <translation>水平集步数</translation>
    </message>
    <message>
        <source>Steps of the threshold level set that moves the boundary onto the boundary level (0 turns layer 3 off).</source>
        <translation>阈值水平集将边界移动到边界水平的步数（0 关闭第 3 层）。</translation>
    </message>
    <message>
        <source>Level-set curvature weight</source>
        <translation>水平集曲率权重</translation>
    </message>
    <message>
        <source>Weight of the curvature (smoothing) term against the contrast term; large values shrink thin vessels.</source>
        <translation>曲率（平滑）项相对于对比项的权重；大值会使细血管收缩。</translation>
    </message>
    <message>
        <source>Layer 4: refinement and clean-up</source>
        <translation>第 4 层：细化与清理</translation>
    </message>
    <message>
        <source>Bone margin</source>
        <translation>骨骼边距</translation>
    </message>
    <message>
        <source>Voxels this close to bone or calcium (above the highest contrast HU) are removed.</source>
        <translation>距骨骼或钙化（高于最高对比 HU）如此近的体素被移除。</translation>
    </message>
    <message>
        <source>Refinement sigma</source>
        <translation>细化 sigma</translation>
    </message>
    <message>
        <source>Recursive Gaussian refinement of the label boundary (thesis ch. 4.1); 0 turns it off.</source>
        <translation>标签边界的递归高斯细化（论文第 4.1 章）；0 关闭。</translation>
    </message>
    <message>
        <source>Guided segmentation (waves from points)</source>
        <translation>引导分割（从点出发的波）</translation>
    </message>
    <message>
        <source>Wave width</source>
        <translation>波宽</translation>
    </message>
    <message>
        <source>Path-length width of one wave; its connected pieces are the vessel&apos;s cross-sections.</source>
        <translation>一道波的路径长度宽度；其连通片即血管的横截面。</translation>
    </message>
    <message>
        <source>Leak area factor</source>
        <translation>泄漏面积因子</translation>
    </message>
    <message>
        <source>A cross-section this many times the narrowest of the 12 before it is a leak and is cut back to that neck (explosion control as in Tschirren 2005).</source>
        <translation>横截面达到其前 12 个中最窄者的此倍数即为泄漏，并被切回到该颈部（爆炸控制，见 Tschirren 2005）。</translation>
    </message>
    <message>
        <source>Smallest leak</source>
        <translation>最小泄漏</translation>
    </message>
    <message>
        <source>Cross-sections smaller than this are never called leaks.</source>
        <translation>小于此值的横截面从不视为泄漏。</translation>
    </message>
    <message>
        <source>Thin vessel</source>
        <translation>细血管</translation>
    </message>
    <message>
        <source>A front whose cross-section is under this (a vessel under 3.2 mm across) grows on down to the thin level: the scanner&apos;s blur dims a tip under 1 mm below the half level of the blood. 0: off.</source>
        <translation>横截面小于此值（直径小于 3.2 mm 的血管）的波前继续生长到细水平：扫描仪的模糊使小于 1 mm 的末梢低于血液的半高水平。0：关闭。</translation>
    </message>
    <message>
        <source>Thin level</source>
        <translation>细水平</translation>
    </message>
    <message>
        <source>The thin level: this fraction of the way from the tissue to the blood, and at least 4 robust standard deviations of the smoothed tissue above it.</source>
        <translation>细水平：从组织到血液路程的此比例，且至少高于平滑后组织 4 个稳健标准差。</translation>
    </message>
    <message>
        <source>Aortic branch length</source>
        <translation>主动脉分支长度</translation>
    </message>
    <message>
        <source>Target aorta: path length followed into a branch (a cross-section under a quarter of the trunk&apos;s).</source>
        <translation>目标主动脉：沿分支追踪的路径长度（横截面小于主干的四分之一）。</translation>
    </message>
    <message>
        <source>Aortic branches (hepatic)</source>
        <translation>主动脉分支（肝）</translation>
    </message>
    <message>
        <source>Target hepatic: the aortic point&apos;s front (the widest) fills the aorta but enters its branches only this far; the other points&apos; fronts grow the tree and cannot pass the aorta.</source>
        <translation>目标肝动脉：主动脉点的波前（最宽）充满主动脉，但只进入其分支此距离；其他点的波前生长血管树，不能穿过主动脉。</translation>
    </message>
    <message>
        <source>Join points by minimal paths</source>
        <translation>以最小路径连接各点</translation>
    </message>
    <message>
        <source>Target hepatic: a point whose front stopped short of the aorta&apos;s (cut at a touching vein or organ) is joined to it along the minimal path on vesselness, and the path is given its lumen. 0: off.</source>
        <translation>目标肝动脉：波前在主动脉之前停止的点（在相邻静脉或器官处被切断）沿血管性上的最小路径与之相连，并赋予该路径管腔。0：关闭。</translation>
    </message>
    <message>
        <source>Organ growing</source>
        <translation>器官生长</translation>
    </message>
    <message>
        <source>Intensity window</source>
        <translation>强度窗</translation>
    </message>
    <message>
        <source>Half-width of the HU window around the points&apos; median, in robust standard deviations of the HU near them.</source>
        <translation>以各点中位数为中心的 HU 窗半宽，单位为其附近 HU 的稳健标准差。</translation>
    </message>
    <message>
        <source>Opening radius</source>
        <translation>开运算半径</translation>
    </message>
    <message>
        <source>Bridges thinner than twice this to touching organs of the same density are cut.</source>
        <translation>与相同密度相邻器官之间细于此值两倍的桥接被切断。</translation>
    </message>
    <message>
        <source>Closing radius</source>
        <translation>闭运算半径</translation>
    </message>
    <message>
        <source>Gaps narrower than twice this inside the organ (small vessels, noise) are taken in.</source>
        <translation>器官内部窄于此值两倍的间隙（小血管、噪声）被纳入。</translation>
    </message>
    <message>
        <source>Reach from the points</source>
        <translation>距各点的范围</translation>
    </message>
    <message>
        <source>The label stays within a box this far around the points.</source>
        <translation>标签保持在各点周围此距离的包围盒内。</translation>
    </message>
    <message>
        <source>Lesion growing</source>
        <translation>病灶生长</translation>
    </message>
    <message>
        <source>Lesion threshold</source>
        <translation>病灶阈值</translation>
    </message>
    <message>
        <source>The lesion&apos;s boundary: this many spreads of the smoothed liver parenchyma (its histogram peak&apos;s full width at half maximum / 2.355) below the peak (hypodense lesions; above it for hyperdense ones), and at least a quarter of the lesion&apos;s contrast.</source>
        <translation>病灶边界：低于平滑肝实质峰值（其直方图峰的半高全宽 / 2.355）此数量的离散度（低密度病灶；高密度病灶则高于峰值），且至少为病灶对比度的四分之一。</translation>
    </message>
    <message>
        <source>Smoothing</source>
        <translation>平滑</translation>
    </message>
    <message>
        <source>Standard deviation of the Gaussian the CT is smoothed with before the threshold.</source>
        <translation>阈值化之前平滑 CT 所用高斯的标准差。</translation>
    </message>
    <message>
        <source>Bridges thinner than twice this (along vessels, to a neighbouring lesion) are cut.</source>
        <translation>细于此值两倍的桥接（沿血管、通向相邻病灶）被切断。</translation>
    </message>
    <message>
        <source>Gaps narrower than twice this (the enhancing rim, vessels through the lesion) are taken in.</source>
        <translation>窄于此值两倍的间隙（强化边缘、穿过病灶的血管）被纳入。</translation>
    </message>
    <message>
        <source>Surface</source>
        <translation>表面</translation>
    </message>
    <message>
        <source>Smoothing iterations</source>
        <translation>平滑迭代次数</translation>
    </message>
    <message>
        <source>Windowed-sinc smoothing iterations (Taubin et al. 1996).</source>
        <translation>窗口化 sinc 平滑的迭代次数（Taubin 等 1996）。</translation>
    </message>
    <message>
        <source>Smoothing passband</source>
        <translation>平滑通带</translation>
    </message>
    <message>
        <source>Windowed-sinc pass band: lower is smoother.</source>
        <translation>窗口化 sinc 的通带：越低越平滑。</translation>
    </message>
    <message>
        <source>Vertex budget</source>
        <translation>顶点预算</translation>
    </message>
    <message>
        <source>Decimate to about this many vertices (thesis: 1,427-2,251 for simulation); 0 keeps every vertex.</source>
        <translation>抽取到约此数量的顶点（论文：模拟用 1,427-2,251）；0 保留所有顶点。</translation>
    </message>
    <message>
        <source>Skeleton</source>
        <translation>骨架</translation>
    </message>
    <message>
        <source>Spur length / radius</source>
        <translation>毛刺长度 / 半径</translation>
    </message>
    <message>
        <source>End branches shorter than this many lumen radii at their junction are spurs of the thinning.</source>
        <translation>在其分叉处短于此数量管腔半径的末端分支是细化产生的毛刺。</translation>
    </message>
    <message>
        <source>Shortest end branch</source>
        <translation>最短末端分支</translation>
    </message>
    <message>
        <source>End branches shorter than this are spurs.</source>
        <translation>短于此值的末端分支是毛刺。</translation>
    </message>
    <message>
        <source>Centerlines</source>
        <translation>中心线</translation>
    </message>
    <message>
        <source>Speed exponent</source>
        <translation>速度指数</translation>
    </message>
    <message>
        <source>Fast-marching speed = (distance to the wall / its maximum)^exponent: higher hugs the medial axis.</source>
        <translation>快速行进速度 =（到管壁的距离 / 其最大值）^指数：越高越贴近中轴。</translation>
    </message>
    <message>
        <source>B-spline knot spacing</source>
        <translation>B 样条节点间距</translation>
    </message>
    <message>
        <source>Knot spacing of the least-squares cubic B-spline that smooths each centerline (thesis ch. 4.1).</source>
        <translation>平滑每条中心线的最小二乘三次 B 样条的节点间距（论文第 4.1 章）。</translation>
    </message>
    <message>
        <source>Sample step</source>
        <translation>采样步长</translation>
    </message>
    <message>
        <source>Spacing of the resampled centerline points.</source>
        <translation>重采样中心线点的间距。</translation>
    </message>
    <message>
        <source>Measurements</source>
        <translation>测量</translation>
    </message>
    <message>
        <source>Section spacing</source>
        <translation>截面间距</translation>
    </message>
    <message>
        <source>Distance between cross-sections.</source>
        <translation>横截面之间的距离。</translation>
    </message>
    <message>
        <source>Junction clearance</source>
        <translation>分叉间隙</translation>
    </message>
    <message>
        <source>Sections closer than 1.5 junction radii plus this to a junction, or this to a segment end, are left out of the figures (branches distort them).</source>
        <translation>距分叉近于 1.5 倍分叉半径加此值、或距段端近于此值的截面不计入数值（分支会使其失真）。</translation>
    </message>
    <message>
        <source>Wall mesh</source>
        <translation>管壁网格</translation>
    </message>
    <message>
        <source>Wall thickness</source>
        <translation>管壁厚度</translation>
    </message>
    <message>
        <source>Offset of the lumen surface (one element layer); an assumption, CT does not resolve the wall: 1.5 mm, the uniform AAA wall of Raghavan et al. 2000 (J Vasc Surg 31:760).</source>
        <translation>管腔表面的偏移（一层单元）；这是一个假设，CT 无法分辨管壁：1.5 mm，即 Raghavan 等 2000 的均匀 AAA 管壁（J Vasc Surg 31:760）。</translation>
    </message>
    <message>
        <source>Sets the largest edge (thin vessels get 0.8 of their radius); thesis meshes: 1,427-2,251 vertices.</source>
        <translation>设定最大边长（细血管取其半径的 0.8）；论文网格：1,427-2,251 个顶点。</translation>
    </message>
    <message>
        <source>Thrombus layer</source>
        <translation>血栓层</translation>
    </message>
    <message>
        <source>1: the AAA sac&apos;s intraluminal thrombus as its own element layer between the lumen and the wall (needs the sac: Vessels &gt; AAA Sac; run with the Raghavan-Vorp wall model). The CLI&apos;s mesh wall --thrombus.</source>
        <translation>1：AAA 瘤囊的腔内血栓作为管腔与管壁之间的独立单元层（需要瘤囊：血管 &gt; AAA 瘤囊；使用 Raghavan-Vorp 管壁模型运行）。命令行为 mesh wall --thrombus。</translation>
    </message>
    <message>
        <source>Material</source>
        <translation>材料</translation>
    </message>
    <message>
        <source>Material model</source>
        <translation>材料模型</translation>
    </message>
    <message>
        <source>0: co-rotational linear elasticity (thesis), 1: St. Venant-Kirchhoff (Green strain; CPU only).</source>
        <translation>0：共旋线弹性（论文），1：St. Venant-Kirchhoff（Green 应变；仅 CPU）。</translation>
    </message>
    <message>
        <source>Young&apos;s modulus</source>
        <translation>杨氏模量</translation>
    </message>
    <message>
        <source>Wall stiffness (thesis patient 1: 4.23 MPa).</source>
        <translation>管壁刚度（论文患者 1：4.23 MPa）。</translation>
    </message>
    <message>
        <source>Poisson&apos;s ratio</source>
        <translation>泊松比</translation>
    </message>
    <message>
        <source>Thesis: 0.23 (printed as 0.23 MPa, a typo).</source>
        <translation>论文：0.23（印为 0.23 MPa，系排印错误）。</translation>
    </message>
    <message>
        <source>Density</source>
        <translation>密度</translation>
    </message>
    <message>
        <source>Wall density (lumped mass).</source>
        <translation>管壁密度（集中质量）。</translation>
    </message>
    <message>
        <source>Integration</source>
        <translation>积分</translation>
    </message>
    <message>
        <source>Time step</source>
        <translation>时间步长</translation>
    </message>
    <message>
        <source>Backward Euler step.</source>
        <translation>后向欧拉步长。</translation>
    </message>
    <message>
        <source>Rayleigh alpha</source>
        <translation>Rayleigh alpha</translation>
    </message>
    <message>
        <source>Mass-proportional damping (thesis: 0).</source>
        <translation>质量比例阻尼（论文：0）。</translation>
    </message>
    <message>
        <source>Rayleigh beta</source>
        <translation>Rayleigh beta</translation>
    </message>
    <message>
        <source>Stiffness-proportional damping (thesis: 0.22 s).</source>
        <translation>刚度比例阻尼（论文：0.22 s）。</translation>
    </message>
    <message>
        <source>PCG tolerance</source>
        <translation>PCG 容差</translation>
    </message>
    <message>
        <source>Relative residual of the implicit solve.</source>
        <translation>隐式求解的相对残差。</translation>
    </message>
    <message>
        <source>PCG iterations</source>
        <translation>PCG 迭代次数</translation>
    </message>
    <message>
        <source>Largest number of PCG iterations per step.</source>
        <translation>每步 PCG 迭代的最大次数。</translation>
    </message>
    <message>
        <source>PCG preconditioner</source>
        <translation>PCG 预条件子</translation>
    </message>
    <message>
        <source>0: block Jacobi (the thesis&apos;s; hundreds of iterations to 1e-8 on a wall), 1: smoothed-aggregation multigrid (tens of iterations, each about five products; set up on the host at the first step; CPU and CUDA). With 1, a tolerance of 1e-8 and a cap of a few hundred every step converges.</source>
        <translation>0：块 Jacobi（论文所用；在管壁上需数百次迭代才到 1e-8），1：光滑聚集多重网格（数十次迭代，每次约五次乘积；在第一步于主机上建立；CPU 和 CUDA）。选 1 时，容差 1e-8、上限数百次，每一步都会收敛。</translation>
    </message>
    <message>
        <source>Thesis rupture protocol</source>
        <translation>论文破裂方案</translation>
    </message>
    <message>
        <source>Ramp start</source>
        <translation>斜坡起点</translation>
    </message>
    <message>
        <source>Mid-vessel pressure at the start of the ramp.</source>
        <translation>斜坡开始时血管中段的压力。</translation>
    </message>
    <message>
        <source>Ramp end</source>
        <translation>斜坡终点</translation>
    </message>
    <message>
        <source>Mid-vessel pressure at the end of the ramp.</source>
        <translation>斜坡结束时血管中段的压力。</translation>
    </message>
    <message>
        <source>Ramp steps</source>
        <translation>斜坡步数</translation>
    </message>
    <message>
        <source>Time steps of the damped ramp (quasi_static 0).</source>
        <translation>阻尼斜坡的时间步数（quasi_static 0）。</translation>
    </message>
    <message>
        <source>Ramp increment</source>
        <translation>斜坡增量</translation>
    </message>
    <message>
        <source>Pressure step between the equilibria of the quasi-static ramp (the onset is then found by bisection to 0.5 % whatever the step).</source>
        <translation>准静态斜坡各平衡态之间的压力步长（随后以二分法将起始点确定到 0.5 %，与步长无关）。</translation>
    </message>
    <message>
        <source>Loaded length</source>
        <translation>加载长度</translation>
    </message>
    <message>
        <source>Share of the wall&apos;s length (about its middle, along its principal axis) that the pressure acts on.</source>
        <translation>压力作用的管壁长度比例（位于其中部，沿其主轴）。</translation>
    </message>
    <message>
        <source>Tear strength</source>
        <translation>撕裂强度</translation>
    </message>
    <message>
        <source>Largest principal stress at which an element tears (the thesis&apos;s tear factor; it does not print a value).</source>
        <translation>单元撕裂时的最大主应力（论文的撕裂因子；论文未给出数值）。</translation>
    </message>
    <message>
        <source>Quasi-static tearing</source>
        <translation>准静态撕裂</translation>
    </message>
    <message>
        <source>Fracture entropy end</source>
        <translation>断裂熵终值</translation>
    </message>
    <message>
        <source>Stop once the fracture entropy passes this (3.9: about 50 torn elements&apos; worth).</source>
        <translation>断裂熵超过此值即停止（3.9：约相当于 50 个撕裂单元）。</translation>
    </message>
    <message>
        <source>Physiological protocol</source>
        <translation>生理方案</translation>
    </message>
    <message>
        <source>Blood pressure</source>
        <translation>血压</translation>
    </message>
    <message>
        <source>Systolic pressure on the lumen.</source>
        <translation>作用于管腔的收缩压。</translation>
    </message>
    <message>
        <source>Wall model</source>
        <translation>管壁模型</translation>
    </message>
    <message>
        <source>Wall Poisson&apos;s ratio</source>
        <translation>管壁泊松比</translation>
    </message>
    <message>
        <source>Near incompressibility of the hyperelastic wall: its bulk modulus from the small-strain shear modulus (wall model 1).</source>
        <translation>超弹性管壁的近不可压缩性：由小应变剪切模量得到其体积模量（管壁模型 1）。</translation>
    </message>
    <message>
        <source>Zero-pressure geometry</source>
        <translation>零压几何</translation>
    </message>
    <message>
        <source>1: the unloaded geometry is found first (backward displacement, Bols et al. 2013) so that the loaded wall is the imaged one; 0: the imaged (loaded) geometry is taken as unloaded (wall model 1).</source>
        <translation>1：先求出无载几何（反向位移，Bols 等 2013），使加载后的管壁即为成像所见；0：成像（加载）几何被视为无载（管壁模型 1）。</translation>
    </message>
    <message>
        <source>Load increments</source>
        <translation>载荷增量</translation>
    </message>
    <message>
        <source>Pressure increments, each solved to equilibrium; one that fails is retried at half the size (wall model 1).</source>
        <translation>压力增量，每个都求解到平衡；失败者以一半大小重试（管壁模型 1）。</translation>
    </message>
    <message>
        <source>Load path time</source>
        <translation>加载路径时间</translation>
    </message>
    <message>
        <source>Wall model 0: simulated time of the damped load path: the pressure ramps up over its first quarter (beta = 0.22 s). The figures are those of the static equilibrium solved after it, which does not depend on the path.</source>
        <translation>管壁模型 0：阻尼加载路径的模拟时间：压力在其前四分之一内上升（beta = 0.22 s）。数值取自之后求解的静态平衡，与路径无关。</translation>
    </message>
    <message>
        <source>Settling time step</source>
        <translation>稳定时间步长</translation>
    </message>
    <message>
        <source>Wall model 0: backward Euler step while settling (the steady state does not depend on it).</source>
        <translation>管壁模型 0：稳定过程中的后向欧拉步长（稳态与之无关）。</translation>
    </message>
    <message>
        <source>Equilibrium tolerance</source>
        <translation>平衡容差</translation>
    </message>
    <message>
        <source>The static equilibrium at the pressure is solved (Newton; GMRES with a sparse Cholesky or LU preconditioner) until ||f_int - f_ext|| / ||f_ext|| is below this; the figures are that state&apos;s. 0 (wall model 0 only): the damped path&apos;s last state.</source>
        <translation>在该压力下求解静态平衡（牛顿法；以稀疏 Cholesky 或 LU 预条件的 GMRES），直到 ||f_int - f_ext|| / ||f_ext|| 低于此值；数值取自该状态。0（仅管壁模型 0）：阻尼路径的最后状态。</translation>
    </message>
    <message>
        <source>Patient (wall strength)</source>
        <translation>患者（管壁强度）</translation>
    </message>
    <message>
        <source>Female</source>
        <translation>女性</translation>
    </message>
    <message>
        <source>1 female, 0 male (Vande Geest 2006 SEX = +-0.5); -1 not given: no rupture index (never assumed).</source>
        <translation>1 女性，0 男性（Vande Geest 2006 SEX = +-0.5）；-1 未给出：无破裂指数（从不假设）。</translation>
    </message>
    <message>
        <source>Family history of AAA</source>
        <translation>AAA 家族史</translation>
    </message>
    <message>
        <source>1 with, 0 without a family history (HIST = +-0.5); -1 not given: no rupture index (never assumed).</source>
        <translation>1 有，0 无家族史（HIST = +-0.5）；-1 未给出：无破裂指数（从不假设）。</translation>
    </message>
    <message>
        <source>Thrombus thickness</source>
        <translation>血栓厚度</translation>
    </message>
    <message>
        <source>Local intraluminal thrombus thickness (ILT).</source>
        <translation>局部腔内血栓厚度（ILT）。</translation>
    </message>
    <message>
        <source>Reference diameter</source>
        <translation>参考直径</translation>
    </message>
    <message>
        <source>Non-aneurysmal aortic diameter for the normalised diameter (NORD); 0: the sac&apos;s neck outer diameter (the patient&apos;s own, from vascusim-cli sac), 20 mm without a sac.</source>
        <translation>用于归一化直径（NORD）的非瘤样主动脉直径；0：瘤囊颈部外径（患者自身的，来自 vascusim-cli sac），无瘤囊时为 20 mm。</translation>
    </message>
    <message>
        <source>Injection</source>
        <translation>注射</translation>
    </message>
    <message>
        <source>Injection rate</source>
        <translation>注射速率</translation>
    </message>
    <message>
        <source>Volume rate of the injected drug mixture at the catheter tip.</source>
        <translation>导管尖端注入的药物混合物的体积速率。</translation>
    </message>
    <message>
        <source>Catheter outer diameter</source>
        <translation>导管外径</translation>
    </message>
    <message>
        <source>Outer diameter of the catheter lying from the tree&apos;s root to its tip, 1 Fr = 1/3 mm (microcatheters 1.7-3.0 Fr); blood passes it through the annulus. 0 leaves it out of the flow.</source>
        <translation>从血管树根部延伸到尖端的导管外径，1 Fr = 1/3 mm（微导管 1.7-3.0 Fr）；血液从环形间隙流过。0 表示在流动中不考虑导管。</translation>
    </message>
    <message>
        <source>Tip snap distance</source>
        <translation>尖端吸附距离</translation>
    </message>
    <message>
        <source>A tip or control point given as a point this near a node is put on the node.</source>
        <translation>以点给出的尖端或控制点距某节点如此近时，被放到该节点上。</translation>
    </message>
    <message>
        <source>Tip reach</source>
        <translation>尖端可达范围</translation>
    </message>
    <message>
        <source>How far a tip or control point given as a point may lie from the vessel tree.</source>
        <translation>以点给出的尖端或控制点距血管树可有多远。</translation>
    </message>
    <message>
        <source>Two-phase drug</source>
        <translation>两相药物</translation>
    </message>
    <message>
        <source>Void fraction</source>
        <translation>空隙率</translation>
    </message>
    <message>
        <source>Gas volume fraction of the injected drug (thesis eq. 6.2, 6.3); the flow is bubbly up to about 0.25.</source>
        <translation>注入药物的气体体积分数（论文式 6.2、6.3）；约 0.25 以下为泡状流。</translation>
    </message>
    <message>
        <source>Gas absorption rate</source>
        <translation>气体吸收速率</translation>
    </message>
    <message>
        <source>Gas absorption rate of the bubbly regime (thesis ch. 6.1: 5-20 ml/min); with the bubble size it gives the bubble rate.</source>
        <translation>泡状流区的气体吸收速率（论文第 6.1 章：5-20 ml/min）；与气泡大小一起给出气泡速率。</translation>
    </message>
    <message>
        <source>Bubble diameter</source>
        <translation>气泡直径</translation>
    </message>
    <message>
        <source>Bubble diameter of the bubbly regime (thesis ch. 6.1: 1.29-2.05 mm).</source>
        <translation>泡状流区的气泡直径（论文第 6.1 章：1.29-2.05 mm）。</translation>
    </message>
    <message>
        <source>Liquid density</source>
        <translation>液体密度</translation>
    </message>
    <message>
        <source>Density of the liquid phase (plasma: 1,060 kg/m^3).</source>
        <translation>液相密度（血浆：1,060 kg/m^3）。</translation>
    </message>
    <message>
        <source>Liquid viscosity</source>
        <translation>液体黏度</translation>
    </message>
    <message>
        <source>Dynamic viscosity of the liquid phase at 37 C (plasma: 3.56 mPa s).</source>
        <translation>液相在 37 C 时的动力黏度（血浆：3.56 mPa s）。</translation>
    </message>
    <message>
        <source>Gas density</source>
        <translation>气体密度</translation>
    </message>
    <message>
        <source>Density of the gas phase.</source>
        <translation>气相密度。</translation>
    </message>
    <message>
        <source>Gas viscosity</source>
        <translation>气体黏度</translation>
    </message>
    <message>
        <source>Dynamic viscosity of the gas phase at 37 C.</source>
        <translation>气相在 37 C 时的动力黏度。</translation>
    </message>
    <message>
        <source>Blood flow</source>
        <translation>血流</translation>
    </message>
    <message>
        <source>Blood carries the drug</source>
        <translation>血液携带药物</translation>
    </message>
    <message>
        <source>1: arterial blood enters at the tree&apos;s root and carries the injected drug; 0: the injected drug flows alone, as the thesis models it (ch. 6).</source>
        <translation>1：动脉血从血管树根部进入并携带注入的药物；0：注入的药物单独流动，如论文所建模（第 6 章）。</translation>
    </message>
    <message>
        <source>Arterial pressure at the root</source>
        <translation>根部动脉压</translation>
    </message>
    <message>
        <source>Mean pressure at the tree&apos;s root, held unless an inflow is given: the hepatic artery&apos;s mean pressure is close to the aorta&apos;s (normal mean arterial pressure 70-105 mmHg).</source>
        <translation>血管树根部的平均压力，未给出流入量时保持不变：肝动脉平均压接近主动脉（正常平均动脉压 70-105 mmHg）。</translation>
    </message>
    <message>
        <source>Arterial inflow</source>
        <translation>动脉流入量</translation>
    </message>
    <message>
        <source>Blood flow into the tree&apos;s root instead of a pressure; 0: the root is held at the arterial pressure. Hepatic arterial flow is about 25 % of the liver&apos;s 100 ml/min per 100 g (Lautt, Hepatic Circulation, 2009): 100-400 ml/min.</source>
        <translation>流入血管树根部的血流量（代替压力）；0：根部保持在动脉压。肝动脉血流约为肝脏每 100 g 100 ml/min 的 25 %（Lautt, Hepatic Circulation, 2009）：100-400 ml/min。</translation>
    </message>
    <message>
        <source>Blood viscosity</source>
        <translation>血液黏度</translation>
    </message>
    <message>
        <source>Apparent viscosity of whole blood at arterial shear rates (about 3.5 mPa s at a haematocrit of 0.45), taken as Newtonian.</source>
        <translation>全血在动脉剪切率下的表观黏度（红细胞压积 0.45 时约 3.5 mPa s），按牛顿流体处理。</translation>
    </message>
    <message>
        <source>Blood density</source>
        <translation>血液密度</translation>
    </message>
    <message>
        <source>Density of whole blood (for the Reynolds number).</source>
        <translation>全血密度（用于雷诺数）。</translation>
    </message>
    <message>
        <source>Outlets</source>
        <translation>出口</translation>
    </message>
    <message>
        <source>Outlets&apos; reference flow</source>
        <translation>出口参考流量</translation>
    </message>
    <message>
        <source>Flow that all outlets together drain at the reference pressure drop, split by Murray&apos;s law (hepatic artery flow is about 100-400 ml/min).</source>
        <translation>所有出口在参考压降下共同排出的流量，按 Murray 定律分配（肝动脉血流约 100-400 ml/min）。</translation>
    </message>
    <message>
        <source>Outlets&apos; reference pressure drop</source>
        <translation>出口参考压降</translation>
    </message>
    <message>
        <source>Pressure drop across the vascular bed beyond the outlets at the reference flow.</source>
        <translation>参考流量下出口以外血管床上的压降。</translation>
    </message>
    <message>
        <source>Pressure beyond the outlets</source>
        <translation>出口以外的压力</translation>
    </message>
    <message>
        <source>Pressure at the far end of the terminal resistances (venous side).</source>
        <translation>终端阻力远端（静脉侧）的压力。</translation>
    </message>
    <message>
        <source>Targeting</source>
        <translation>靶向</translation>
    </message>
    <message>
        <source>Tumour bed resistance factor</source>
        <translation>肿瘤床阻力因子</translation>
    </message>
    <message>
        <source>Terminal resistance of the tumour&apos;s outlets times this (below 1 for a hypervascular tumour).</source>
        <translation>肿瘤出口的终端阻力乘以此值（富血供肿瘤小于 1）。</translation>
    </message>
    <message>
        <source>Filling</source>
        <translation>充盈</translation>
    </message>
    <message>
        <source>Filling steps</source>
        <translation>充盈步数</translation>
    </message>
    <message>
        <source>Time steps from the start of the injection to the last outlet&apos;s arrival.</source>
        <translation>从注射开始到到达最后一个出口的时间步数。</translation>
    </message>
    <message>
        <source>Working angle</source>
        <translation>工作角度</translation>
    </message>
    <message>
        <source>Working C-arm angle</source>
        <translation>C 臂工作角度</translation>
    </message>
    <message>
        <source>1: the LAO/RAO and cranial/caudal angles that show the path from the root to the tip with the least foreshortening and overlap (WorkingAngle.h); 0: none.</source>
        <translation>1：以最小缩短和重叠显示从根部到尖端路径的 LAO/RAO 和头/足位角度（WorkingAngle.h）；0：无。</translation>
    </message>
    <message>
        <source>Territories</source>
        <translation>供血区域</translation>
    </message>
    <message>
        <source>Hepatic outlet reach</source>
        <translation>肝出口范围</translation>
    </message>
    <message>
        <source>An outlet whose end lies this near the liver feeds liver tissue; the others (gastroduodenal, gastric) feed none.</source>
        <translation>末端距肝脏如此近的出口供应肝组织；其他出口（胃十二指肠、胃）不供应。</translation>
    </message>
    <message>
        <source>Tumour perfusion factor</source>
        <translation>肿瘤灌注因子</translation>
    </message>
    <message>
        <source>Arterial perfusion of tumour tissue per volume over the liver&apos;s: a hypervascular HCC draws several times the surrounding liver&apos;s arterial flow (CT perfusion series report about 3-5 times).</source>
        <translation>肿瘤组织单位体积的动脉灌注与肝脏之比：富血供 HCC 获得周围肝脏动脉血流的数倍（CT 灌注系列报告约 3-5 倍）。</translation>
    </message>
    <message>
        <source>Outlets from territories</source>
        <translation>按供血区域确定出口</translation>
    </message>
    <message>
        <source>1: with a liver label, an outlet&apos;s resistance follows the tissue it feeds; 0: Murray&apos;s law of the terminal radius alone.</source>
        <translation>1：有肝脏标签时，出口阻力取决于其供应的组织；0：仅按终端半径的 Murray 定律。</translation>
    </message>
    <message>
        <source>Inlet</source>
        <translation>入口</translation>
    </message>
    <message>
        <source>Inlet mean velocity</source>
        <translation>入口平均速度</translation>
    </message>
    <message>
        <source>over the inlet&apos;s section (the end of the largest vessel), parabolic, ramped up from rest</source>
        <translation>入口截面（最大血管的末端）上的平均值，抛物线分布，从静止逐渐增加</translation>
    </message>
    <message>
        <source>Inlet flow rate</source>
        <translation>入口流量</translation>
    </message>
    <message>
        <source>&gt; 0: replaces the mean velocity</source>
        <translation>&gt; 0：代替平均速度</translation>
    </message>
    <message>
        <source>Outlet pressure</source>
        <translation>出口压力</translation>
    </message>
    <message>
        <source>at every other vessel end (gauge: the pressures reported are relative to it)</source>
        <translation>在其他每个血管末端（表压：报告的压力均相对于此）</translation>
    </message>
    <message>
        <source>Stenosis figures</source>
        <translation>狭窄数值</translation>
    </message>
    <message>
        <source>Compare at</source>
        <translation>比较位置</translation>
    </message>
    <message>
        <source>the sections upstream and downstream of the throat the velocity ratios compare with (thesis: 6 mm in the hand, 30 mm in the heart)</source>
        <translation>速度比所比较的喉部上游和下游截面（论文：手部 6 mm，心脏 30 mm）</translation>
    </message>
    <message>
        <source>Particles</source>
        <translation>粒子</translation>
    </message>
    <message>
        <source>Particle spacing</source>
        <translation>粒子间距</translation>
    </message>
    <message>
        <source>0: a fifth of the inlet&apos;s radius</source>
        <translation>0：入口半径的五分之一</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>时间</translation>
    </message>
    <message>
        <source>End time</source>
        <translation>结束时间</translation>
    </message>
    <message>
        <source>0: twice the inflow&apos;s ramp (two quarter-wave periods of the vessel)</source>
        <translation>0：流入斜坡的两倍（血管的两个四分之一波周期）</translation>
    </message>
    <message>
        <source>Frames</source>
        <translation>帧</translation>
    </message>
    <message>
        <source>frames kept over the run</source>
        <translation>整个运行中保留的帧数</translation>
    </message>
    <message>
        <source>the lattice the particles were seeded on: it sets their mass and the smoothing length</source>
        <translation>粒子播撒所在的格点：它决定粒子质量和光滑长度</translation>
    </message>
    <message>
        <source>Smoothing length</source>
        <translation>光滑长度</translation>
    </message>
    <message>
        <source>h as a multiple of the spacing (the support is 2h); at 2 the quartic kernel&apos;s first moment on a lattice is within 0.2 % of the identity (5.7 % at 1.3: sph-kernel), so pressure gradients come out right</source>
        <translation>h 为间距的倍数（支撑域为 2h）；取 2 时，四次核在格点上的一阶矩与恒等式相差 0.2 % 以内（1.3 时为 5.7 %：sph-kernel），因而压力梯度正确</translation>
    </message>
    <message>
        <source>Fluid</source>
        <translation>流体</translation>
    </message>
    <message>
        <source>Rest density</source>
        <translation>静止密度</translation>
    </message>
    <message>
        <source>blood 1060 (thesis Table 5.1)</source>
        <translation>血液 1060（论文表 5.1）</translation>
    </message>
    <message>
        <source>Dynamic viscosity</source>
        <translation>动力黏度</translation>
    </message>
    <message>
        <source>blood at high shear about 3.5e-3 (thesis: 3.56e-3)</source>
        <translation>高剪切下的血液约 3.5e-3（论文：3.56e-3）</translation>
    </message>
    <message>
        <source>the gas share of the mixture particles (thesis Table 5.1: 0.2 at the needle injection) where the input gives none: rest density and viscosity mixed with air&apos;s (1.205 kg/m^3, 1.86e-5 Pa s)</source>
        <translation>输入未给出时混合粒子的气体份额（论文表 5.1：针头注射时为 0.2）：静止密度和黏度与空气的（1.205 kg/m^3，1.86e-5 Pa s）混合</translation>
    </message>
    <message>
        <source>Numerical sound speed</source>
        <translation>数值声速</translation>
    </message>
    <message>
        <source>at least 10 times the largest flow speed keeps the density within about 1 % (Monaghan 1994)</source>
        <translation>至少为最大流速的 10 倍，可使密度保持在约 1 % 以内（Monaghan 1994）</translation>
    </message>
    <message>
        <source>Reference pressure</source>
        <translation>参考压力</translation>
    </message>
    <message>
        <source>the gauge pressure the rest density stands for (blood flow: the outlets&apos; level): the dynamics work on the pressure above it, every pressure reported adds it back, and prescribed pressures are gauge (FluidModel.h)</source>
        <translation>静止密度所代表的表压（血流：出口水平）：动力学基于高于它的压力，报告的每个压力都加回它，给定的压力为表压（FluidModel.h）</translation>
    </message>
    <message>
        <source>Numerics</source>
        <translation>数值方法</translation>
    </message>
    <message>
        <source>Density diffusion</source>
        <translation>密度扩散</translation>
    </message>
    <message>
        <source>delta of the delta-SPH term (Molteni &amp; Colagrossi 2009; 0 switches it off)</source>
        <translation>delta-SPH 项的 delta（Molteni &amp; Colagrossi 2009；0 关闭）</translation>
    </message>
    <message>
        <source>Courant number</source>
        <translation>Courant 数</translation>
    </message>
    <message>
        <source>the adaptive step&apos;s safety factor</source>
        <translation>自适应步长的安全系数</translation>
    </message>
    <message>
        <source>Gravity x</source>
        <translation>重力 x</translation>
    </message>
    <message>
        <source>patient frame (LPS)</source>
        <translation>患者坐标系（LPS）</translation>
    </message>
    <message>
        <source>Gravity y</source>
        <translation>重力 y</translation>
    </message>
    <message>
        <source>patient frame (LPS): a supine patient&apos;s gravity is +9.81 (posterior)</source>
        <translation>患者坐标系（LPS）：仰卧患者的重力为 +9.81（后方）</translation>
    </message>
    <message>
        <source>Gravity z</source>
        <translation>重力 z</translation>
    </message>
    <message>
        <source>simulated time</source>
        <translation>模拟时间</translation>
    </message>
    <message>
        <source>Guards</source>
        <translation>保护</translation>
    </message>
    <message>
        <source>Density guard</source>
        <translation>密度保护</translation>
    </message>
    <message>
        <source>the run stops when a fluid particle&apos;s density is further than this from the rest density (relative)</source>
        <translation>流体粒子的密度偏离静止密度超过此值（相对）时运行停止</translation>
    </message>
    <message>
        <source>Escape margin</source>
        <translation>逸出边距</translation>
    </message>
    <message>
        <source>the run stops when a particle leaves the particles&apos; starting box grown by this</source>
        <translation>粒子离开按此值扩大的粒子初始包围盒时运行停止</translation>
    </message>
    <message>
        <source>Reorder every</source>
        <translation>重排间隔</translation>
    </message>
    <message>
        <source>the particles are sorted by neighbour cell every so many steps</source>
        <translation>每隔这么多步按邻居单元对粒子排序</translation>
    </message>
    <message>
        <source>Body force x</source>
        <translation>体积力 x</translation>
    </message>
    <message>
        <source>a driving force per unit mass (a pressure gradient over the density) in a periodic pipe or channel</source>
        <translation>周期管道或通道中的单位质量驱动力（压力梯度除以密度）</translation>
    </message>
    <message>
        <source>Body force y</source>
        <translation>体积力 y</translation>
    </message>
    <message>
        <source>as body_force_x_m_s2</source>
        <translation>同 body_force_x_m_s2</translation>
    </message>
    <message>
        <source>Body force z</source>
        <translation>体积力 z</translation>
    </message>
    <message>
        <source>Body force frequency</source>
        <translation>体积力频率</translation>
    </message>
    <message>
        <source>&gt; 0: the body force oscillates as cos(2 pi f t) (Womersley flow); 0: steady</source>
        <translation>&gt; 0：体积力按 cos(2 pi f t) 振荡（Womersley 流）；0：定常</translation>
    </message>
    <message>
        <source>Domain</source>
        <translation>区域</translation>
    </message>
    <message>
        <source>Periodic length x</source>
        <translation>周期长度 x</translation>
    </message>
    <message>
        <source>validation channels: &gt; 0 makes the domain [0, L) wrap around along x (0: open)</source>
        <translation>验证通道：&gt; 0 使区域 [0, L) 沿 x 周期环绕（0：开放）</translation>
    </message>
    <message>
        <source>Periodic length y</source>
        <translation>周期长度 y</translation>
    </message>
    <message>
        <source>as periodic_x_mm, along y</source>
        <translation>同 periodic_x_mm，沿 y</translation>
    </message>
    <message>
        <source>Periodic length z</source>
        <translation>周期长度 z</translation>
    </message>
    <message>
        <source>as periodic_x_mm, along z</source>
        <translation>同 periodic_x_mm，沿 z</translation>
    </message>
    <message>
        <source>Walls</source>
        <translation>壁面</translation>
    </message>
    <message>
        <source>Free surface</source>
        <translation>自由表面</translation>
    </message>
    <message>
        <source>1 for a liquid with a free surface (a tank, a dam break): the walls hold no suction above it; 0 in vessels</source>
        <translation>1 表示有自由表面的液体（水箱、溃坝）：壁面在其上方不产生吸力；血管中为 0</translation>
    </message>
    <message>
        <source>Tension in the fluid</source>
        <translation>流体中的张力</translation>
    </message>
    <message>
        <source>1: a density below the rest density pulls the fluid together (Tait&apos;s negative pressure; vessels, tanks); 0: a liquid that breaks up (a stream falling from a needle, a splash): each particle&apos;s density is held at its rest density or above, its pressure at 0 or above, and the density guard reads compression only</source>
        <translation>1：低于静止密度的密度会把流体拉拢（Tait 负压；血管、水箱）；0：会破碎的液体（从针头落下的液流、飞溅）：每个粒子的密度保持在静止密度或以上，压力保持在 0 或以上，密度保护只读取压缩</translation>
    </message>
    <message>
        <source>Wall repulsion</source>
        <translation>壁面排斥</translation>
    </message>
    <message>
        <source>the walls&apos; Lennard-Jones backstop (thesis ch. 5.4, Monaghan 1994): a wall particle closer than 0.9 spacings pushes a fluid particle away with D ((r0 / r)^12 - (r0 / r)^4) / r, D this times c0^2 (0.01: about the largest flow speed squared); it holds fluid out of walls thinner than the kernel, but empties a throat a few particles across (sph-stenosis at 0.2 mm: area ratio 4.97 against 3.34 without): 0, off</source>
        <translation>壁面的 Lennard-Jones 挡板（论文第 5.4 章，Monaghan 1994）：距离小于 0.9 个间距的壁面粒子以 D ((r0 / r)^12 - (r0 / r)^4) / r 推开流体粒子，D 为此值乘以 c0^2（0.01：约为最大流速的平方）；它能把流体挡在比核更薄的壁外，但会使仅几个粒子宽的喉部变空（sph-stenosis 在 0.2 mm 时：面积比 4.97，无挡板时为 3.34）：0，关闭</translation>
    </message>
    <message>
        <source>Absorption distance</source>
        <translation>吸收距离</translation>
    </message>
    <message>
        <source>tracer particles (an injected drug) this close to a wall&apos;s surface are absorbed and counted (0: none)</source>
        <translation>距壁面如此近的示踪粒子（注入的药物）被吸收并计数（0：无）</translation>
    </message>
    <message>
        <source>Needle</source>
        <translation>针头</translation>
    </message>
    <message>
        <source>Needle bore</source>
        <translation>针头内径</translation>
    </message>
    <message>
        <source>the needle&apos;s inner diameter (16 G: 1.19 mm); the particles a third of it unless the spacing is given</source>
        <translation>针头的内径（16 G：1.19 mm）；未给出间距时粒子取其三分之一</translation>
    </message>
    <message>
        <source>Generation rate</source>
        <translation>生成速率</translation>
    </message>
    <message>
        <source>particles of the run&apos;s spacing a second (thesis Table 5.1: 300)</source>
        <translation>每秒生成运行间距大小的粒子数（论文表 5.1：300）</translation>
    </message>
    <message>
        <source>Collection box</source>
        <translation>收集盒</translation>
    </message>
    <message>
        <source>Collection box depth</source>
        <translation>收集盒深度</translation>
    </message>
    <message>
        <source>its floor below the vessel&apos;s lowest wall</source>
        <translation>其底部低于血管最低壁面的距离</translation>
    </message>
    <message>
        <source>Collection box margin</source>
        <translation>收集盒边距</translation>
    </message>
    <message>
        <source>its sides beyond the open ends</source>
        <translation>其侧面超出开口端的距离</translation>
    </message>
    <message>
        <source>0: a third of the bore</source>
        <translation>0：内径的三分之一</translation>
    </message>
    <message>
        <source>0: twice a free fall from the needle to the box&apos;s floor</source>
        <translation>0：从针头自由落体到盒底时间的两倍</translation>
    </message>
    <message>
        <source>Tissue</source>
        <translation>组织</translation>
    </message>
    <message>
        <source>Thermal diffusivity</source>
        <translation>热扩散率</translation>
    </message>
    <message>
        <source>soft tissue about 0.14 mm^2/s (Duck 1990, Physical Properties of Tissue)</source>
        <translation>软组织约 0.14 mm^2/s（Duck 1990, Physical Properties of Tissue）</translation>
    </message>
    <message>
        <source>Cube edge</source>
        <translation>立方体边长</translation>
    </message>
    <message>
        <source>faces held at body temperature</source>
        <translation>各面保持体温</translation>
    </message>
    <message>
        <source>Cells per edge</source>
        <translation>每边单元数</translation>
    </message>
    <message>
        <source>the grid has cells + 1 nodes per edge</source>
        <translation>网格每边有 单元数 + 1 个节点</translation>
    </message>
    <message>
        <source>Initial rise</source>
        <translation>初始温升</translation>
    </message>
    <message>
        <source>peak of the initial temperature rise (the slowest mode)</source>
        <translation>初始温升的峰值（最慢模态）</translation>
    </message>
    <message>
        <source>the step as a fraction of forward Euler&apos;s stability limit; above 1 the scheme is unstable and the guard stops the run</source>
        <translation>步长占前向欧拉稳定极限的比例；大于 1 时格式不稳定，保护机制会停止运行</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>运行</translation>
    </message>
    <message>
        <source>Frame every N steps</source>
        <translation>每 N 步一帧</translation>
    </message>
    <message>
        <source>a frame after every N steps (0: not by steps; with both intervals 0, only the first and the last frame)</source>
        <translation>每 N 步后一帧（0：不按步数；两个间隔均为 0 时，只有第一帧和最后一帧）</translation>
    </message>
    <message>
        <source>Frame every</source>
        <translation>帧间隔</translation>
    </message>
    <message>
        <source>a frame each time the run&apos;s axis (simulated time in s, or pressure in kPa) passes a multiple of this (0: not by the axis)</source>
        <translation>运行的轴（模拟时间 s，或压力 kPa）每越过此值的倍数时一帧（0：不按轴）</translation>
    </message>
    <message>
        <source>Keep every Nth frame</source>
        <translation>每 N 帧保留一帧</translation>
    </message>
    <message>
        <source>keep every Nth frame taken (large runs); the first and the last are always kept, and the run lists which</source>
        <translation>所取的帧中每 N 帧保留一帧（大型运行）；第一帧和最后一帧总是保留，运行会列出保留了哪些</translation>
    </message>
    <message>
        <source>Step limit</source>
        <translation>步数上限</translation>
    </message>
    <message>
        <source>a run that has not reached its end after this many steps stops with a message (a collapsing time step)</source>
        <translation>此步数后仍未到达终点的运行会停止并给出消息（时间步长崩塌）</translation>
    </message>
    <message>
        <source>Grid</source>
        <translation>网格</translation>
    </message>
    <message>
        <source>Cells along the longest edge</source>
        <translation>最长边上的单元数</translation>
    </message>
    <message>
        <source>the grid&apos;s resolution (the thesis demo: 256); cubic cells</source>
        <translation>网格分辨率（论文演示：256）；立方体单元</translation>
    </message>
    <message>
        <source>Longest step</source>
        <translation>最大时间步长</translation>
    </message>
    <message>
        <source>the step is shorter when the flow is fast (cfl)</source>
        <translation>流动较快时步长更短（cfl）</translation>
    </message>
    <message>
        <source>cells the fastest flow crosses in one step (semi-Lagrangian advection is stable beyond 1)</source>
        <translation>最快流动在一步内穿过的单元数（半拉格朗日平流在大于 1 时仍稳定）</translation>
    </message>
    <message>
        <source>Solver</source>
        <translation>求解器</translation>
    </message>
    <message>
        <source>Velocity advection</source>
        <translation>速度平流</translation>
    </message>
    <message>
        <source>0 semi-Lagrangian, 1 MacCormack with the limiter (Selle et al. 2008)</source>
        <translation>0 半拉格朗日，1 带限制器的 MacCormack（Selle et al. 2008）</translation>
    </message>
    <message>
        <source>Projection tolerance</source>
        <translation>投影容差</translation>
    </message>
    <message>
        <source>relative residual of the pressure solve (MGPCG)</source>
        <translation>压力求解的相对残差（MGPCG）</translation>
    </message>
    <message>
        <source>Projection iterations</source>
        <translation>投影迭代次数</translation>
    </message>
    <message>
        <source>conjugate-gradient iterations per projection at most</source>
        <translation>每次投影的共轭梯度迭代上限</translation>
    </message>
    <message>
        <source>Vorticity confinement</source>
        <translation>涡量约束</translation>
    </message>
    <message>
        <source>epsilon of Fedkiw et al. 2001 (thesis eq. 7.9): f = epsilon h (N x w)</source>
        <translation>Fedkiw et al. 2001 的 epsilon（论文式 7.9）：f = epsilon h (N x w)</translation>
    </message>
    <message>
        <source>Vortex particle strength</source>
        <translation>涡粒子强度</translation>
    </message>
    <message>
        <source>epsilon of the particles&apos; forcing (thesis eqs. 7.20-7.23); too large is unstable</source>
        <translation>粒子作用力的 epsilon（论文式 7.20-7.23）；过大会不稳定</translation>
    </message>
    <message>
        <source>Vortex particle radius</source>
        <translation>涡粒子半径</translation>
    </message>
    <message>
        <source>Source</source>
        <translation>源</translation>
    </message>
    <message>
        <source>Vortex particles</source>
        <translation>涡粒子</translation>
    </message>
    <message>
        <source>born at the source over its duration (thesis: 1,100 in the demo, 400 in EVH)</source>
        <translation>在源处于其持续时间内生成（论文：演示 1,100 个，EVH 400 个）</translation>
    </message>
    <message>
        <source>Smoke emission</source>
        <translation>烟雾排放量</translation>
    </message>
    <message>
        <source>particulate mass the cautery releases (an assumption: published rates vary widely)</source>
        <translation>电刀释放的颗粒物质量（假定值：文献报道差异很大）</translation>
    </message>
    <message>
        <source>Plume temperature</source>
        <translation>烟羽温度</translation>
    </message>
    <message>
        <source>the plume&apos;s rise above the ambient at the source</source>
        <translation>源处烟羽高于环境的温升</translation>
    </message>
    <message>
        <source>Plume speed</source>
        <translation>烟羽速度</translation>
    </message>
    <message>
        <source>initial velocity of the plume, along gravity&apos;s up (liver ablation: lower, thesis)</source>
        <translation>烟羽初速度，沿重力反方向（肝消融：较低，论文）</translation>
    </message>
    <message>
        <source>Smoke onset</source>
        <translation>烟雾开始时间</translation>
    </message>
    <message>
        <source>when the smoke starts after the tool&apos;s contact (EVH: 9 s, thesis)</source>
        <translation>器械接触后烟雾开始的时间（EVH：9 s，论文）</translation>
    </message>
    <message>
        <source>Smoke duration</source>
        <translation>烟雾持续时间</translation>
    </message>
    <message>
        <source>how long it emits</source>
        <translation>排放持续的时间</translation>
    </message>
    <message>
        <source>Plume cooling</source>
        <translation>烟羽冷却</translation>
    </message>
    <message>
        <source>rate at which the plume&apos;s temperature rise relaxes (mixing, walls)</source>
        <translation>烟羽温升衰减的速率（混合、壁面）</translation>
    </message>
    <message>
        <source>Suction</source>
        <translation>抽吸</translation>
    </message>
    <message>
        <source>Suction on</source>
        <translation>抽吸开启</translation>
    </message>
    <message>
        <source>when the suction starts</source>
        <translation>抽吸开始的时间</translation>
    </message>
    <message>
        <source>Suction off</source>
        <translation>抽吸关闭</translation>
    </message>
    <message>
        <source>when it stops</source>
        <translation>抽吸停止的时间</translation>
    </message>
    <message>
        <source>View</source>
        <translation>视野</translation>
    </message>
    <message>
        <source>Mass extinction coefficient</source>
        <translation>质量消光系数</translation>
    </message>
    <message>
        <source>Beer-Lambert&apos;s K_m (8.7 m^2/g: Mulholland &amp; Croarkin 2000)</source>
        <translation>Beer-Lambert 的 K_m（8.7 m^2/g：Mulholland &amp; Croarkin 2000）</translation>
    </message>
    <message>
        <source>Visibility threshold</source>
        <translation>可见度阈值</translation>
    </message>
    <message>
        <source>a pixel is obscured below this transmittance</source>
        <translation>透射率低于此值时像素视为被遮挡</translation>
    </message>
    <message>
        <source>Obscuration sampling</source>
        <translation>遮挡采样间隔</translation>
    </message>
    <message>
        <source>interval of the obscuration curve</source>
        <translation>遮挡曲线的时间间隔</translation>
    </message>
    <message>
        <source>the clamped Gaussian&apos;s control radius r, in cells</source>
        <translation>截断高斯核的控制半径 r，以单元计</translation>
    </message>
    <message>
        <source>smoke evacuation flow at the suction port (scenes with a port); liver-ablation&apos;s 20 l/min is calibrated to remove 85 % of the smoke in 10 s (Chou 2024) in the box phantom at 64 cells</source>
        <translation>抽吸口的排烟流量（带抽吸口的场景）；肝消融的 20 l/min 经校准，在 64 单元的长方体体模中 10 s 内清除 85 % 的烟雾（Chou 2024）</translation>
    </message>
    <message>
        <source>1: the wall in static equilibrium at each pressure of the ramp, the tearing onset bracketed by bisection to 0.5 %, one element released per equilibrium (does not depend on the ramp); 0: the thesis&apos;s damped ramp, every element over the limit torn in the same step (the onset lags the ramp).</source>
        <translation>1：管壁在斜坡的每个压力下处于静态平衡，撕裂起始以二分法界定到 0.5 %，每个平衡态释放一个单元（与斜坡无关）；0：论文的阻尼斜坡，超过极限的所有单元在同一步撕裂（起始滞后于斜坡）。</translation>
    </message>
    <message>
        <source>Equilibrium iteration</source>
        <translation>平衡迭代</translation>
    </message>
    <message>
        <source>Quasi-static tearing&apos;s equilibria. 0: full Newton (the pressure&apos;s load stiffness in the tangent, GMRES with a Cholesky preconditioner; CPU). 1: modified Newton without the load stiffness, its symmetric tangent by multigrid conjugate gradients (about 3 times the updates; CPU and CUDA, the same tears on both).</source>
        <translation>准静态撕裂的平衡态。0：完全牛顿法（切线中含压力的载荷刚度，GMRES 配 Cholesky 预条件器；CPU）。1：不含载荷刚度的修正牛顿法，其对称切线以多重网格共轭梯度求解（更新次数约 3 倍；CPU 与 CUDA，两者撕裂相同）。</translation>
    </message>
    <message>
        <source>Particle shifting</source>
        <translation>粒子位移</translation>
    </message>
    <message>
        <source>A of the shift&apos;s coefficient A h |v| (Lind et al. 2012, Skillen et al. 2013; 0: off): the drift also moves each fluid particle down the gradient of the particles&apos; concentration, which keeps a fast jet&apos;s shear layer from tearing into streaks and voids; vessels only (not with a free surface or without tension)</source>
        <translation>位移系数 A h |v| 中的 A（Lind 等 2012，Skillen 等 2013；0：关闭）：漂移时每个流体粒子还沿粒子浓度梯度下降方向移动，使高速射流的剪切层不会撕裂成条纹和空洞；仅用于血管（不用于自由表面或无张力流体）</translation>
    </message>
    <message>
        <source>Shift correction</source>
        <translation>位移修正</translation>
    </message>
    <message>
        <source>1: with particle shifting, a shifted particle&apos;s velocity follows it to where the shift moves it, v + dr . grad v (Lind et al. 2012&apos;s Taylor correction); 0: the particle keeps its velocity</source>
        <translation>1：启用粒子位移时，被位移粒子的速度随其移到位移后的位置，v + dr . grad v（Lind 等 2012 的泰勒修正）；0：粒子保持原速度</translation>
    </message>
    <message>
        <source>1 (the clinical analysis): quadratic (10-node) tets with the Raghavan &amp; Vorp 2000 hyperelastic AAA wall (nearly incompressible) and the Wang 2001 thrombus where the wall mesh has one, static equilibrium by load increments and Newton&apos;s method (CPU; on 2 cores about 20 s for 15,000 tets, 45 s for 30,000 with a thrombus layer, 85 s for the demo&apos;s 31,000 around a wide sac); 0: the Material group&apos;s law on linear tets, a damped load path then the equilibrium (GPU path possible; linear tets lock in bending and near incompressibility).</source>
        <translation>1（临床分析）：二次（10 节点）四面体，采用 Raghavan &amp; Vorp 2000 超弹性 AAA 管壁（近乎不可压缩），管壁网格含血栓时采用 Wang 2001 血栓模型，按载荷增量以牛顿法求静力平衡（CPU；在 2 核上 1.5 万个四面体约 20 秒，含血栓层的 3 万个约 45 秒，演示病例宽瘤囊周围的 3.1 万个约 85 秒）；0：材料组的本构律作用于线性四面体，先经阻尼加载路径，再求平衡（可用 GPU；线性四面体在弯曲和近乎不可压缩时会锁死）。</translation>
    </message>
    <message>
        <source>Finite Particle Method</source>
        <translation>有限粒子法</translation>
    </message>
    <message>
        <source>1: the density rate from the velocity&apos;s divergence and the density diffusion&apos;s gradient by the first-order Finite Particle Method (thesis eq. 5.17), exact for linear fields where walls or a free surface cut the kernel; 0: the SPH sums</source>
        <translation>1：密度变化率由速度散度、密度扩散项的梯度由一阶有限粒子法（论文式 5.17）计算，在壁面或自由表面截断核函数处对线性场仍精确；0：SPH 求和</translation>
    </message>
    <message>
        <source>Density by summation</source>
        <translation>求和密度</translation>
    </message>
    <message>
        <source>1: each fluid particle&apos;s density from how closely its neighbours stand, m_i sum_j W_ij scaled so that the seeding lattice reads the rest density (no continuity equation, so no density diffusion: delta_sph and fpm have nothing to act on); it cannot drift from the particles&apos; spacing, which the continuity density did in a stenotic jet&apos;s wake; vessels only (a fluid that fills its walls); 0: the continuity equation</source>
        <translation>1：每个流体粒子的密度由其邻居的间距得出，m_i sum_j W_ij，经缩放使初始晶格读出静止密度（无连续性方程，因此无密度扩散：delta_sph 和 fpm 不起作用）；它不会像连续性密度在狭窄射流尾流中那样偏离粒子间距；仅用于血管（充满其壁的流体）；0：连续性方程</translation>
    </message>
    <message>
        <source>Density relaxation time</source>
        <translation>密度松弛时间</translation>
    </message>
    <message>
        <source>&gt; 0: with the continuity equation, each fluid particle&apos;s density also relaxes towards its summation density over this time, so that it cannot drift from the particles&apos; spacing over longer times (a stenotic jet&apos;s wake thinned out by 30 % at a constant continuity density) while keeping the continuity density&apos;s smoothness over shorter ones; a drift at rate r leaves the two about r times this apart; vessels only; 0: off</source>
        <translation>&gt; 0：使用连续性方程时，每个流体粒子的密度还在此时间内向其求和密度松弛，使其在较长时间内不会偏离粒子间距（狭窄射流的尾流在连续性密度不变时稀疏了 30 %），而在较短时间内保持连续性密度的平滑；以速率 r 的漂移使两者相差约 r 乘以此时间；仅用于血管；0：关闭</translation>
    </message>
    <message>
        <source>Fluid loss guard</source>
        <translation>流体损失保护</translation>
    </message>
    <message>
        <source>&gt; 0: the run stops when the fluid&apos;s net outflow through the open ends (outflow - inflow, the mass ledger&apos;s) exceeds this share of its first fluid mass: a vessel whose particles thin out while their densities still read full (the continuity density&apos;s drift: density_relaxation_s) empties, and its figures are not a flow&apos;s; 0: off (a domain that fills: an injection)</source>
        <translation>&gt; 0：当流体通过开放端的净流出（流出 - 流入，按质量账）超过其初始流体质量的此比例时，运行停止：粒子变稀而密度仍显示为满的血管（连续性密度的漂移：density_relaxation_s）会排空，其数值不代表流动；0：关闭（逐渐充满的区域：注射）</translation>
    </message>
    <message>
        <source>Shifting speed floor</source>
        <translation>位移速度下限</translation>
    </message>
    <message>
        <source>&gt; 0: the shift&apos;s coefficient is A h max(|v|, this), so that slow zones (a stenosis&apos;s separation zone) are shifted too, where with |v| alone the particles clump and leave voids; the flow&apos;s largest speed makes it the delta+-SPH shift (Sun et al. 2017); 0: |v| alone</source>
        <translation>&gt; 0：位移系数为 A h max(|v|, 此值)，使慢速区（狭窄后的分离区）也得到位移；若只用 |v|，那里的粒子会聚集成团并留下空隙；取流动的最大速度即为 delta+-SPH 位移（Sun 等，2017）；0：只用 |v|</translation>
    </message>
    <message>
        <source>Blood flow&apos;s wall pressure</source>
        <translation>血流的壁面压力</translation>
    </message>
    <message>
        <source>1: the lumen carries the blood pressure plus the time-averaged wall pressure of the study&apos;s newest blood-flow run (relative to its outlets; one-way coupling), scaled with the load; 0: a uniform pressure (wall model 1).</source>
        <translation>1：管腔承受血压加上研究中最新血流计算的时间平均壁面压力（相对于其出口；单向耦合），随载荷缩放；0：均匀压力（血管壁模型 1）。</translation>
    </message>
</context>
<context>
    <name>vsim::Progress</name>
    <message>
        <source>painting the anatomy</source>
        <translation>绘制解剖结构</translation>
    </message>
    <message>
        <source>scanner noise</source>
        <translation>扫描仪噪声</translation>
    </message>
    <message>
        <source>rendering truth labels</source>
        <translation>渲染真值标签</translation>
    </message>
    <message>
        <source>writing DICOM</source>
        <translation>写入 DICOM</translation>
    </message>
    <message>
        <source>decoding DICOM</source>
        <translation>解码 DICOM</translation>
    </message>
    <message>
        <source>DICOM imported</source>
        <translation>DICOM 已导入</translation>
    </message>
    <message>
        <source>reading DICOM headers</source>
        <translation>读取 DICOM 头信息</translation>
    </message>
    <message>
        <source>phantom written</source>
        <translation>体模已写入</translation>
    </message>
    <message>
        <source>point-spread function</source>
        <translation>点扩散函数</translation>
    </message>
    <message>
        <source>resampling</source>
        <translation>重采样</translation>
    </message>
    <message>
        <source>aortic lumen followed</source>
        <translation>已追踪主动脉管腔</translation>
    </message>
    <message>
        <source>outer contour</source>
        <translation>外轮廓</translation>
    </message>
    <message>
        <source>thrombus and wall</source>
        <translation>血栓与管壁</translation>
    </message>
    <message>
        <source>perpendicular diameters</source>
        <translation>垂直直径</translation>
    </message>
    <message>
        <source>sac measured</source>
        <translation>瘤囊已测量</translation>
    </message>
    <message>
        <source>fast marching</source>
        <translation>快速行进</translation>
    </message>
    <message>
        <source>minimal paths</source>
        <translation>最小路径</translation>
    </message>
    <message>
        <source>centerlines</source>
        <translation>中心线</translation>
    </message>
    <message>
        <source>segmented</source>
        <translation>已分割</translation>
    </message>
    <message>
        <source>liver</source>
        <translation>肝脏</translation>
    </message>
    <message>
        <source>smoothing</source>
        <translation>平滑</translation>
    </message>
    <message>
        <source>growing</source>
        <translation>区域生长</translation>
    </message>
    <message>
        <source>opening</source>
        <translation>开运算</translation>
    </message>
    <message>
        <source>closing</source>
        <translation>闭运算</translation>
    </message>
    <message>
        <source>lesion grown</source>
        <translation>病灶生长完成</translation>
    </message>
    <message>
        <source>organ grown</source>
        <translation>器官生长完成</translation>
    </message>
    <message>
        <source>partial-volume radii</source>
        <translation>部分容积半径</translation>
    </message>
    <message>
        <source>thinning</source>
        <translation>细化</translation>
    </message>
    <message>
        <source>pruning</source>
        <translation>剪枝</translation>
    </message>
    <message>
        <source>skeleton</source>
        <translation>骨架</translation>
    </message>
    <message>
        <source>measuring</source>
        <translation>测量中</translation>
    </message>
    <message>
        <source>vesselness</source>
        <translation>血管性</translation>
    </message>
    <message>
        <source>finding contrast-filled vessels</source>
        <translation>查找造影剂充盈的血管</translation>
    </message>
    <message>
        <source>segmenting vessels</source>
        <translation>分割血管</translation>
    </message>
    <message>
        <source>level set</source>
        <translation>水平集</translation>
    </message>
    <message>
        <source>clean-up</source>
        <translation>清理</translation>
    </message>
    <message>
        <source>iso-surface</source>
        <translation>等值面</translation>
    </message>
    <message>
        <source>decimating</source>
        <translation>网格简化</translation>
    </message>
    <message>
        <source>surface</source>
        <translation>表面</translation>
    </message>
    <message>
        <source>damping</source>
        <translation>阻尼</translation>
    </message>
    <message>
        <source>quasi-static tearing at %1</source>
        <translation>准静态撕裂，压力 %1</translation>
    </message>
    <message>
        <source>lesions and margins</source>
        <translation>病灶与边缘</translation>
    </message>
    <message>
        <source>ranking catheter positions by coverage</source>
        <translation>按覆盖度排序导管位置</translation>
    </message>
    <message>
        <source>flow solved</source>
        <translation>流动已求解</translation>
    </message>
    <message>
        <source>done</source>
        <translation>完成</translation>
    </message>
    <message>
        <source>ranking catheter positions</source>
        <translation>排序导管位置</translation>
    </message>
    <message>
        <source>perfusion territories</source>
        <translation>灌注区域</translation>
    </message>
    <message>
        <source>liver voxels</source>
        <translation>肝脏体素</translation>
    </message>
    <message>
        <source>working angle</source>
        <translation>工作角度</translation>
    </message>
    <message>
        <source>converting to HU</source>
        <translation>转换为 HU</translation>
    </message>
    <message>
        <source>reading %1</source>
        <translation>读取 %1</translation>
    </message>
    <message>
        <source>read</source>
        <translation>已读取</translation>
    </message>
    <message>
        <source>vessel ends from the centerlines</source>
        <translation>由中心线得到血管末端</translation>
    </message>
    <message>
        <source>particles from the lumen label</source>
        <translation>由管腔标签生成粒子</translation>
    </message>
    <message>
        <source>the lumen&apos;s surface for the wall loads</source>
        <translation>用于壁面载荷的管腔表面</translation>
    </message>
    <message>
        <source>demo study written</source>
        <translation>演示研究已写入</translation>
    </message>
    <message>
        <source>mask read</source>
        <translation>掩模已读取</translation>
    </message>
    <message>
        <source>AAA section</source>
        <translation>AAA 部分</translation>
    </message>
    <message>
        <source>report</source>
        <translation>报告</translation>
    </message>
    <message>
        <source>lumen surface</source>
        <translation>管腔表面</translation>
    </message>
    <message>
        <source>remeshing</source>
        <translation>重新划分网格</translation>
    </message>
    <message>
        <source>wall</source>
        <translation>管壁</translation>
    </message>
    <message>
        <source>smoke scene</source>
        <translation>烟雾场景</translation>
    </message>
</context>
<context>
    <name>vsim::RunStatus</name>
    <message>
        <source>force residual %1 (tolerance %2)</source>
        <translation>力残差 %1（容差 %2）</translation>
    </message>
    <message>
        <source>converged</source>
        <translation>已收敛</translation>
    </message>
    <message>
        <source>converged, %1</source>
        <translation>已收敛，%1</translation>
    </message>
    <message>
        <source>%1 of %2 solves ended above their tolerance</source>
        <translation>%2 次求解中有 %1 次结束时高于容差</translation>
    </message>
    <message>
        <source> at the %1-iteration cap</source>
        <translation>，达到 %1 次迭代上限</translation>
    </message>
    <message>
        <source>, worst relative residual %1 (tolerance %2)</source>
        <translation>，最差相对残差 %1（容差 %2）</translation>
    </message>
    <message>
        <source>not converged: %1</source>
        <translation>未收敛：%1</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <source>stopped by a guard</source>
        <translation>被保护检查终止</translation>
    </message>
    <message>
        <source>stopped by its end condition</source>
        <translation>因结束条件停止</translation>
    </message>
    <message>
        <source>pressure</source>
        <translation>压力</translation>
    </message>
    <message>
        <source>time</source>
        <translation>时间</translation>
    </message>
    <message>
        <source> at %1 %2 of %3 %4</source>
        <translation>，%1 达到 %2 / %3 %4</translation>
    </message>
    <message>
        <source>NOT CONVERGED (%1)</source>
        <translation>未收敛（%1）</translation>
    </message>
    <message>
        <source>STOPPED EARLY (%1)</source>
        <translation>提前停止（%1）</translation>
    </message>
    <message>
        <source>, %1 of them at the %2-iteration cap</source>
        <translation>，其中 %1 次达到 %2 次迭代上限</translation>
    </message>
</context>
<context>
    <name>vsim::ViewMeasurement</name>
    <message>
        <source>mean %1 HU, SD %2 HU, area %3 mm2</source>
        <translation>平均 %1 HU，标准差 %2 HU，面积 %3 mm2</translation>
    </message>
    <message>
        <source>straight distance between the two points in the patient frame (mm)</source>
        <translation>患者坐标系中两点之间的直线距离（mm）</translation>
    </message>
    <message>
        <source>angle at the middle point between the two arms (degrees)</source>
        <translation>中间点处两臂之间的夹角（度）</translation>
    </message>
    <message>
        <source>CT values (HU) of the voxels nearest the in-plane samples inside the ellipse, one sample per finest voxel spacing squared: mean and sample standard deviation; area of the ellipse, pi a b (mm2)</source>
        <translation>椭圆内平面采样点最近体素的 CT 值（HU），每个最小体素间距平方取一个样本：平均值与样本标准差；椭圆面积 pi a b（mm2）</translation>
    </message>
</context>
<context>
    <name>vsim::app::SegmentNames</name>
    <message>
        <source>unnamed (nodes %1-%2)</source>
        <translation>未命名（节点 %1-%2）</translation>
    </message>
</context>
<context>
    <name>vsim::gui::DicomImportDialog</name>
    <message>
        <source>Import DICOM</source>
        <translation>导入 DICOM</translation>
    </message>
    <message>
        <source>Folder, DICOMDIR or file</source>
        <translation>文件夹、DICOMDIR 或文件</translation>
    </message>
    <message>
        <source>Browse...</source>
        <translation>浏览...</translation>
    </message>
    <message>
        <source>Scan</source>
        <translation>扫描</translation>
    </message>
    <message>
        <source>Patient / study / series</source>
        <translation>患者 / 检查 / 序列</translation>
    </message>
    <message>
        <source>Modality</source>
        <translation>模态</translation>
    </message>
    <message>
        <source>Slices</source>
        <translation>层数</translation>
    </message>
    <message>
        <source>Voxel spacing (mm)</source>
        <translation>体素间距 (mm)</translation>
    </message>
    <message>
        <source>Warnings</source>
        <translation>警告</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <source>Import</source>
        <translation>导入</translation>
    </message>
    <message>
        <source>DICOM folder</source>
        <translation>DICOM 文件夹</translation>
    </message>
    <message>
        <source>Reading DICOM headers...</source>
        <translation>正在读取 DICOM 头...</translation>
    </message>
    <message>
        <source>(no name)</source>
        <translation>（无姓名）</translation>
    </message>
    <message>
        <source>no ID</source>
        <translation>无 ID</translation>
    </message>
    <message>
        <source>(no description)</source>
        <translation>（无描述）</translation>
    </message>
    <message numerus="yes">
        <source>%n file(s), %1 series</source>
        <translation>
            <numerusform>%n 个文件，%1 个序列</numerusform>
        </translation>
    </message>
    <message>
        <source> (making previews)</source>
        <translation>（正在生成预览）</translation>
    </message>
</context>
<context>
    <name>vsim::gui::DrugDeliveryPanel</name>
    <message>
        <source>DSA-like view at the working angle</source>
        <translation>工作角度下的类 DSA 视图</translation>
    </message>
    <message>
        <source>Keep this run (the next one is added beside it)</source>
        <translation>保留此运行（下一次运行添加在其旁）</translation>
    </message>
    <message>
        <source>The liver as a label: perfusion territories, coverage grade and feeders</source>
        <translation>肝脏标签：灌注区域、覆盖等级和供血支</translation>
    </message>
    <message>
        <source>The tumour as a label (with a liver label): its lesions, margins and coverage</source>
        <translation>肿瘤标签（需肝脏标签）：其病灶、边缘和覆盖</translation>
    </message>
    <message>
        <source>x, y, z mm; empty: the root</source>
        <translation>x, y, z mm；空：根部</translation>
    </message>
    <message>
        <source>x, y, z, radius mm; empty: none</source>
        <translation>x, y, z, 半径 mm；空：无</translation>
    </message>
    <message>
        <source>x, y, z; ... mm; empty: the first branches</source>
        <translation>x, y, z; ... mm；空：第一级分支</translation>
    </message>
    <message>
        <source>largest end; or a name, a segment number, or x, y, z mm on it</source>
        <translation>最大末端；或名称、段号，或其上的 x, y, z mm</translation>
    </message>
    <message>
        <source>Blood enters through this segment; the tree beyond it is modelled</source>
        <translation>血液经此段进入；其后的血管树被建模</translation>
    </message>
    <message>
        <source>segment numbers, e.g. 3, 7</source>
        <translation>段号，例如 3, 7</translation>
    </message>
    <message>
        <source>segment numbers; or untick a feeder below</source>
        <translation>段号；或在下方取消勾选供血支</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>Pick</source>
        <translation>拾取</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>添加</translation>
    </message>
    <message>
        <source>Click a branch of the shown run in the 3D view to add it as a feeder</source>
        <translation>在 3D 视图中点击所示运行的一个分支，将其添加为供血支</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>运行</translation>
    </message>
    <message>
        <source>Catheter tip</source>
        <translation>导管尖端</translation>
    </message>
    <message>
        <source>Tumour</source>
        <translation>肿瘤</translation>
    </message>
    <message>
        <source>Tumour radius (picked)</source>
        <translation>肿瘤半径（拾取）</translation>
    </message>
    <message>
        <source>Control points</source>
        <translation>控制点</translation>
    </message>
    <message>
        <source>Liver label</source>
        <translation>肝脏标签</translation>
    </message>
    <message>
        <source>Tumour label</source>
        <translation>肿瘤标签</translation>
    </message>
    <message>
        <source>Blood enters at</source>
        <translation>血液进入位置</translation>
    </message>
    <message>
        <source>Feeders added</source>
        <translation>已添加的供血支</translation>
    </message>
    <message>
        <source>Feeders removed</source>
        <translation>已移除的供血支</translation>
    </message>
    <message>
        <source>Outlet</source>
        <translation>出口</translation>
    </message>
    <message>
        <source>The outlet&apos;s vessel (anatomical name when known)</source>
        <translation>出口所在血管（已知时为解剖名称）</translation>
    </message>
    <message>
        <source>Drug share (%)</source>
        <translation>药物份额 (%)</translation>
    </message>
    <message>
        <source>Share of the injected drug leaving through this outlet (%)</source>
        <translation>经此出口流出的注入药物份额 (%)</translation>
    </message>
    <message>
        <source>Arrival (s)</source>
        <translation>到达 (s)</translation>
    </message>
    <message>
        <source>Time for the drug front to reach the outlet from the catheter tip (s)</source>
        <translation>药物前沿从导管尖端到达出口的时间 (s)</translation>
    </message>
    <message>
        <source>Feeder (tick: keep)</source>
        <translation>供血支（勾选：保留）</translation>
    </message>
    <message>
        <source>A branch entering the tumour or its margin; untick to remove it from the plan</source>
        <translation>进入肿瘤或其边缘的分支；取消勾选即从计划中移除</translation>
    </message>
    <message>
        <source>Segment</source>
        <translation>段</translation>
    </message>
    <message>
        <source>The feeder&apos;s segment number in the kept tree</source>
        <translation>供血支在保留血管树中的段号</translation>
    </message>
    <message>
        <source>Radius (mm)</source>
        <translation>半径 (mm)</translation>
    </message>
    <message>
        <source>Lumen radius of the feeder (mm)</source>
        <translation>供血支的管腔半径 (mm)</translation>
    </message>
    <message>
        <source>Found</source>
        <translation>找到方式</translation>
    </message>
    <message>
        <source>Found automatically, or added by hand</source>
        <translation>自动找到，或手动添加</translation>
    </message>
    <message>
        <source>Drug reaches it</source>
        <translation>药物可达</translation>
    </message>
    <message>
        <source>Whether drug injected at the current tip reaches this feeder</source>
        <translation>在当前尖端注入的药物是否到达此供血支</translation>
    </message>
    <message>
        <source>The projection as a DSA-like image (the opacified tree, the path to the tip denser)</source>
        <translation>类 DSA 图像形式的投影（显影的血管树，通往尖端的路径更浓）</translation>
    </message>
    <message>
        <source>added by hand</source>
        <translation>手动添加</translation>
    </message>
    <message>
        <source>enters lesion + margin</source>
        <translation>进入病灶 + 边缘</translation>
    </message>
    <message>
        <source>feeds the lesion</source>
        <translation>供应病灶</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>是</translation>
    </message>
    <message>
        <source>no</source>
        <translation>否</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>（无）</translation>
    </message>
    <message>
        <source>Tip pressure %1 mmHg; last outlet reached after %2 s.</source>
        <translation>尖端压力 %1 mmHg；%2 s 后到达最后一个出口。</translation>
    </message>
    <message>
        <source>&lt;br&gt;Control point %1: drug %2 ml/min two-phase, %3 ml/min liquid (%4 % lower)</source>
        <translation>&lt;br&gt;控制点 %1：药物 %2 ml/min（两相），%3 ml/min（液相）（低 %4 %）</translation>
    </message>
    <message>
        <source>&lt;br&gt;Blood: %1 ml/min at the root, %2 ml/min reaching the tip (own flow %3); the drug is %4 % of the flow below it; the catheter fills %5 % of the lumen%6.</source>
        <translation>&lt;br&gt;血液：根部 %1 ml/min，到达尖端 %2 ml/min（自身流量 %3）；药物占其下方流量的 %4 %；导管占据管腔的 %5 %%6。</translation>
    </message>
    <message>
        <source>: WEDGED</source>
        <translation>：楔入</translation>
    </message>
    <message>
        <source>&lt;br&gt;&lt;b&gt;Coverage grade %1&lt;/b&gt;: territory %2 ml (%3 ml of tumour); drug to tumour %4 %, non-tumour liver %5 %, extrahepatic %6 %.</source>
        <translation>&lt;br&gt;&lt;b&gt;覆盖等级 %1&lt;/b&gt;：供血区域 %2 ml（肿瘤 %3 ml）；药物至肿瘤 %4 %，非肿瘤肝脏 %5 %，肝外 %6 %。</translation>
    </message>
    <message>
        <source>&lt;br&gt;Lesion %1: %2 mm, %3 mm margin; %4 % covered, margin %5 % (grade %6).</source>
        <translation>&lt;br&gt;病灶 %1：%2 mm，边缘 %3 mm；覆盖 %4 %，边缘 %5 %（等级 %6）。</translation>
    </message>
    <message>
        <source>%1 (segment %2, %3 mm)</source>
        <translation>%1（段 %2，%3 mm）</translation>
    </message>
    <message>
        <source>&lt;br&gt;Feeders: %1.</source>
        <translation>&lt;br&gt;供血支：%1。</translation>
    </message>
    <message>
        <source>none found</source>
        <translation>未找到</translation>
    </message>
    <message>
        <source>%1 %2 %</source>
        <translation>%1 %2 %</translation>
    </message>
    <message>
        <source>&lt;br&gt;Drug leaving the liver: %1.</source>
        <translation>&lt;br&gt;离开肝脏的药物：%1。</translation>
    </message>
    <message>
        <source>&lt;br&gt;Tumour share %1 % (%2 outlets).</source>
        <translation>&lt;br&gt;肿瘤份额 %1 %（%2 个出口）。</translation>
    </message>
    <message>
        <source>&lt;br&gt;Best tip: node %1 delivers %2 % to the tumour.</source>
        <translation>&lt;br&gt;最佳尖端：节点 %1 向肿瘤输送 %2 %。</translation>
    </message>
    <message>
        <source>&lt;br&gt;&lt;b&gt;Working angle %1 %2, %3 %4&lt;/b&gt; (the projection below): the path foreshortened %5 %, overlapped %6 % (from the front: %7 %, %8 %).</source>
        <translation>&lt;br&gt;&lt;b&gt;工作角度 %1 %2，%3 %4&lt;/b&gt;（下方投影）：路径缩短 %5 %，重叠 %6 %（正位：%7 %，%8 %）。</translation>
    </message>
    <message>
        <source>LAO</source>
        <translation>LAO</translation>
    </message>
    <message>
        <source>RAO</source>
        <translation>RAO</translation>
    </message>
    <message>
        <source>cranial</source>
        <translation>头位</translation>
    </message>
    <message>
        <source>caudal</source>
        <translation>足位</translation>
    </message>
    <message>
        <source>never</source>
        <translation>从不</translation>
    </message>
    <message>
        <source>Drug flow (ml/min; grey: none)</source>
        <translation>药物流量（ml/min；灰色：无）</translation>
    </message>
    <message>
        <source>time</source>
        <translation>时间</translation>
    </message>
    <message>
        <source>s</source>
        <translation>s</translation>
    </message>
</context>
<context>
    <name>vsim::gui::EndoscopePanel</name>
    <message>
        <source>The centerline segment the camera flies along</source>
        <translation>相机沿其飞行的中心线段</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>播放</translation>
    </message>
    <message>
        <source>Fly the camera along the segment at the speed set</source>
        <translation>以设定速度沿该段飞行相机</translation>
    </message>
    <message>
        <source>Forwards (start to end)</source>
        <translation>向前（起点到终点）</translation>
    </message>
    <message>
        <source>Backwards (end to start)</source>
        <translation>向后（终点到起点）</translation>
    </message>
    <message>
        <source> mm/s</source>
        <translation> mm/s</translation>
    </message>
    <message>
        <source>Flight speed along the centerline (mm per second)</source>
        <translation>沿中心线的飞行速度（毫米每秒）</translation>
    </message>
    <message>
        <source>The camera&apos;s position along the segment (mm from its start)</source>
        <translation>相机沿该段的位置（距起点的 mm）</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>Focal length of the probe&apos;s lens (mm): longer narrows the field of view (4 mm sensor)</source>
        <translation>探头镜头的焦距 (mm)：越长视野越窄（4 mm 传感器）</translation>
    </message>
    <message>
        <source>Distance in focus (mm along the view); out of focus the picture blurs and grows noisy</source>
        <translation>对焦距离（沿视线的 mm）；失焦时图像模糊且噪声增多</translation>
    </message>
    <message>
        <source>Aperture as an f-number: smaller lets in more light and shortens the depth of field</source>
        <translation>以 f 数表示的光圈：越小进光越多、景深越浅</translation>
    </message>
    <message>
        <source>Focus on Centre</source>
        <translation>对焦于中心</translation>
    </message>
    <message>
        <source>Set the focus distance to the wall at the picture&apos;s centre</source>
        <translation>将对焦距离设为图像中心处的管壁</translation>
    </message>
    <message>
        <source>Segment</source>
        <translation>段</translation>
    </message>
    <message>
        <source>Focal length</source>
        <translation>焦距</translation>
    </message>
    <message>
        <source>Focus distance</source>
        <translation>对焦距离</translation>
    </message>
    <message>
        <source>Aperture (f-number)</source>
        <translation>光圈（f 数）</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
</context>
<context>
    <name>vsim::gui::FieldTitles</name>
    <message>
        <source>von Mises stress (kPa)</source>
        <translation>von Mises 应力（kPa）</translation>
    </message>
    <message>
        <source>maximum principal stress (kPa)</source>
        <translation>最大主应力（kPa）</translation>
    </message>
    <message>
        <source>wall strength (kPa)</source>
        <translation>管壁强度（kPa）</translation>
    </message>
    <message>
        <source>rupture potential index</source>
        <translation>破裂潜能指数</translation>
    </message>
    <message>
        <source>material</source>
        <translation>材料</translation>
    </message>
    <message>
        <source>displacement (mm)</source>
        <translation>位移（mm）</translation>
    </message>
    <message>
        <source>displacement x (mm)</source>
        <translation>位移 x（mm）</translation>
    </message>
    <message>
        <source>displacement y (mm)</source>
        <translation>位移 y（mm）</translation>
    </message>
    <message>
        <source>displacement z (mm)</source>
        <translation>位移 z（mm）</translation>
    </message>
    <message>
        <source>drug flow (ml/min)</source>
        <translation>药物流量（ml/min）</translation>
    </message>
    <message>
        <source>drug flow, liquid only (ml/min)</source>
        <translation>药物流量，仅液相（ml/min）</translation>
    </message>
    <message>
        <source>flow (ml/min)</source>
        <translation>流量（ml/min）</translation>
    </message>
    <message>
        <source>mean velocity (mm/s)</source>
        <translation>平均流速（mm/s）</translation>
    </message>
    <message>
        <source>pressure at the segment&apos;s start (mmHg)</source>
        <translation>段起点压力（mmHg）</translation>
    </message>
    <message>
        <source>pressure at the segment&apos;s end (mmHg)</source>
        <translation>段终点压力（mmHg）</translation>
    </message>
    <message>
        <source>Reynolds number</source>
        <translation>雷诺数</translation>
    </message>
    <message>
        <source>injected share of the flow (%)</source>
        <translation>注射液占流量的比例（%）</translation>
    </message>
    <message>
        <source>downstream of the catheter&apos;s tip</source>
        <translation>导管尖端下游</translation>
    </message>
    <message>
        <source>drug front enters the segment (s)</source>
        <translation>药物前沿进入该段（s）</translation>
    </message>
    <message>
        <source>drug front leaves the segment (s)</source>
        <translation>药物前沿离开该段（s）</translation>
    </message>
    <message>
        <source>filled length (mm)</source>
        <translation>充盈长度（mm）</translation>
    </message>
    <message>
        <source>filled fraction</source>
        <translation>充盈比例</translation>
    </message>
    <message>
        <source>speed (m/s)</source>
        <translation>速率（m/s）</translation>
    </message>
    <message>
        <source>velocity x (m/s)</source>
        <translation>速度 x（m/s）</translation>
    </message>
    <message>
        <source>velocity y (m/s)</source>
        <translation>速度 y（m/s）</translation>
    </message>
    <message>
        <source>velocity z (m/s)</source>
        <translation>速度 z（m/s）</translation>
    </message>
    <message>
        <source>pressure (Pa)</source>
        <translation>压力（Pa）</translation>
    </message>
    <message>
        <source>density (kg/m³)</source>
        <translation>密度（kg/m³）</translation>
    </message>
    <message>
        <source>void fraction</source>
        <translation>空隙率</translation>
    </message>
    <message>
        <source>wall particle</source>
        <translation>壁粒子</translation>
    </message>
    <message>
        <source>open boundary</source>
        <translation>开放边界</translation>
    </message>
    <message>
        <source>tracer</source>
        <translation>示踪剂</translation>
    </message>
    <message>
        <source>time-averaged wall shear stress (Pa)</source>
        <translation>时间平均壁面剪应力（Pa）</translation>
    </message>
    <message>
        <source>oscillatory shear index</source>
        <translation>振荡剪切指数</translation>
    </message>
    <message>
        <source>wall pressure (Pa)</source>
        <translation>壁面压力（Pa）</translation>
    </message>
    <message>
        <source>smoke density (mg/m³)</source>
        <translation>烟雾密度（mg/m³）</translation>
    </message>
    <message>
        <source>temperature rise (K)</source>
        <translation>温升（K）</translation>
    </message>
</context>
<context>
    <name>vsim::gui::HelpWindow</name>
    <message>
        <source>VascuSim User Guide</source>
        <translation>VascuSim 用户指南</translation>
    </message>
</context>
<context>
    <name>vsim::gui::InteractiveWall</name>
    <message>
        <source>von Mises (kPa)</source>
        <translation>von Mises 应力 (kPa)</translation>
    </message>
</context>
<context>
    <name>vsim::gui::MainWindow</name>
    <message>
        <source>%1: cancelled, nothing changed</source>
        <translation>%1：已取消，未做任何更改</translation>
    </message>
    <message>
        <source>%1: done</source>
        <translation>%1：完成</translation>
    </message>
    <message>
        <source>Artifact</source>
        <translation>对象</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>类型</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>状态</translation>
    </message>
    <message>
        <source>Study</source>
        <translation>研究</translation>
    </message>
    <message>
        <source>Workflow</source>
        <translation>工作流程</translation>
    </message>
    <message>
        <source>A step is running: wait for it or cancel it</source>
        <translation>有步骤正在运行：请等待或取消</translation>
    </message>
    <message>
        <source>Open or create a study first (File menu)</source>
        <translation>请先打开或创建研究（文件菜单）</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>No study</source>
        <translation>无研究</translation>
    </message>
    <message>
        <source>%1 (read-only) - VascuSim</source>
        <translation>%1（只读）- VascuSim</translation>
    </message>
    <message>
        <source>%1[*] - VascuSim</source>
        <translation>%1[*] - VascuSim</translation>
    </message>
    <message>
        <source>ID %1</source>
        <translation>ID %1</translation>
    </message>
    <message>
        <source>image</source>
        <translation>图像</translation>
    </message>
    <message>
        <source>label</source>
        <translation>标签</translation>
    </message>
    <message>
        <source>surface</source>
        <translation>表面</translation>
    </message>
    <message>
        <source>volume mesh</source>
        <translation>体网格</translation>
    </message>
    <message>
        <source>skeleton</source>
        <translation>骨架</translation>
    </message>
    <message>
        <source>network</source>
        <translation>网络</translation>
    </message>
    <message>
        <source>report</source>
        <translation>报告</translation>
    </message>
    <message>
        <source>run</source>
        <translation>运行</translation>
    </message>
    <message>
        <source>measurement</source>
        <translation>测量</translation>
    </message>
    <message>
        <source>damaged</source>
        <translation>已损坏</translation>
    </message>
    <message numerus="yes">
        <source>%n warning(s)</source>
        <translation>
            <numerusform>%n 条警告</numerusform>
        </translation>
    </message>
    <message>
        <source>%1, made by &quot;%2&quot; on %3</source>
        <translation>%1，由“%2”于 %3 生成</translation>
    </message>
    <message>
        <source>%1 failed</source>
        <translation>%1 失败</translation>
    </message>
    <message>
        <source>Opened read-only: the study is being written by %1</source>
        <translation>以只读方式打开：研究正被 %1 写入</translation>
    </message>
    <message>
        <source>Study in use</source>
        <translation>研究正在使用</translation>
    </message>
    <message>
        <source>The study is being written by %1.
Open it read-only, or break the lock if you are sure that program no longer runs.</source>
        <translation>研究正被 %1 写入。
以只读方式打开；如果确定该程序已不再运行，也可以解除锁定。</translation>
    </message>
    <message>
        <source>Open Read-Only</source>
        <translation>以只读方式打开</translation>
    </message>
    <message>
        <source>Break the Lock...</source>
        <translation>解除锁定...</translation>
    </message>
    <message>
        <source>Break the lock</source>
        <translation>解除锁定</translation>
    </message>
    <message>
        <source>If %1 still runs, both programs will write the study and results can be lost. Break the lock?</source>
        <translation>如果 %1 仍在运行，两个程序将同时写入研究，结果可能丢失。解除锁定吗？</translation>
    </message>
    <message>
        <source>Open study</source>
        <translation>打开研究</translation>
    </message>
    <message>
        <source>Study opened with problems</source>
        <translation>研究打开时有问题</translation>
    </message>
    <message>
        <source>New study</source>
        <translation>新建研究</translation>
    </message>
    <message>
        <source>Save study</source>
        <translation>保存研究</translation>
    </message>
    <message>
        <source>Save study as</source>
        <translation>研究另存为</translation>
    </message>
    <message>
        <source>Show image</source>
        <translation>显示图像</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>未保存的更改</translation>
    </message>
    <message>
        <source>Save the changes to this study before closing?</source>
        <translation>关闭前保存对此研究的更改吗？</translation>
    </message>
    <message>
        <source>Import volume</source>
        <translation>导入体数据</translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation>导入 %1</translation>
    </message>
    <message>
        <source>Import label</source>
        <translation>导入标签</translation>
    </message>
    <message>
        <source>The study has no CT image for the label&apos;s grid: import the CT first.</source>
        <translation>研究中没有与标签网格对应的 CT 图像：请先导入 CT。</translation>
    </message>
    <message>
        <source>Not Hounsfield units</source>
        <translation>不是 Hounsfield 单位</translation>
    </message>
    <message>
        <source>%1

Rescale to HU (HU = slope x stored value + intercept):</source>
        <translation>%1

重新缩放为 HU（HU = 斜率 x 存储值 + 截距）：</translation>
    </message>
    <message>
        <source>Import DICOM</source>
        <translation>导入 DICOM</translation>
    </message>
    <message>
        <source>Label Editing</source>
        <translation>标签编辑</translation>
    </message>
    <message>
        <source>Paint</source>
        <translation>绘制</translation>
    </message>
    <message>
        <source>Erase</source>
        <translation>擦除</translation>
    </message>
    <message>
        <source>Paint vessel voxels with the left button in any MPR view (one undo step per stroke)</source>
        <translation>在任一 MPR 视图中用左键绘制血管体素（每一笔为一个撤销步骤）</translation>
    </message>
    <message>
        <source>Erase vessel voxels with the left button in any MPR view</source>
        <translation>在任一 MPR 视图中用左键擦除血管体素</translation>
    </message>
    <message>
        <source> Radius </source>
        <translation> 半径 </translation>
    </message>
    <message>
        <source>Sphere</source>
        <translation>球形</translation>
    </message>
    <message>
        <source>3D brush: paint or erase a ball of the radius through the slices, not a disc in the view&apos;s plane</source>
        <translation>3D 画笔：穿过各层绘制或擦除该半径的球，而不是视图平面内的圆盘</translation>
    </message>
    <message>
        <source> Paint as </source>
        <translation> 绘制为 </translation>
    </message>
    <message>
        <source>Lumen</source>
        <translation>管腔</translation>
    </message>
    <message>
        <source>Thrombus</source>
        <translation>血栓</translation>
    </message>
    <message>
        <source>Wall</source>
        <translation>管壁</translation>
    </message>
    <message>
        <source>The label value the brush paints: the lumen, or the thrombus and wall of an AAA sac label</source>
        <translation>画笔绘制的标签值：管腔，或 AAA 瘤囊标签的血栓和管壁</translation>
    </message>
    <message>
        <source>Remove Island</source>
        <translation>移除孤岛</translation>
    </message>
    <message>
        <source>Remove the connected piece of the label at the cursor (click it in an MPR view first)</source>
        <translation>移除光标处标签的连通片（先在 MPR 视图中点击它）</translation>
    </message>
    <message>
        <source>Apply Edits</source>
        <translation>应用编辑</translation>
    </message>
    <message>
        <source>Discard Edits</source>
        <translation>放弃编辑</translation>
    </message>
    <message>
        <source>Add the edited label to the study as a new artifact (the original stays)</source>
        <translation>将编辑后的标签作为新对象加入研究（原标签保留）</translation>
    </message>
    <message>
        <source>Label edits: %1 voxels painted, %2 erased</source>
        <translation>标签编辑：绘制 %1 个体素，擦除 %2 个</translation>
    </message>
    <message>
        <source>Edit label</source>
        <translation>编辑标签</translation>
    </message>
    <message>
        <source>The study has no vessel label: segment the vessels first.</source>
        <translation>研究中没有血管标签：请先分割血管。</translation>
    </message>
    <message>
        <source>No labelled voxel within 3 mm of the cursor</source>
        <translation>光标 3 mm 内没有标签体素</translation>
    </message>
    <message>
        <source>Island removed: %1 voxels erased in all</source>
        <translation>已移除孤岛：共擦除 %1 个体素</translation>
    </message>
    <message>
        <source>Apply label edits</source>
        <translation>应用标签编辑</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>文件(&amp;F)</translation>
    </message>
    <message>
        <source>&amp;New Study...</source>
        <translation>新建研究(&amp;N)...</translation>
    </message>
    <message>
        <source>Study folder (*.vsim)</source>
        <translation>研究文件夹 (*.vsim)</translation>
    </message>
    <message>
        <source>&amp;Open Study...</source>
        <translation>打开研究(&amp;O)...</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>最近打开(&amp;R)</translation>
    </message>
    <message>
        <source>Import &amp;DICOM...</source>
        <translation>导入 DICOM(&amp;D)...</translation>
    </message>
    <message>
        <source>Ctrl+D</source>
        <translation>Ctrl+D</translation>
    </message>
    <message>
        <source>&amp;Import Volume...</source>
        <translation>导入体数据(&amp;I)...</translation>
    </message>
    <message>
        <source>Ctrl+I</source>
        <translation>Ctrl+I</translation>
    </message>
    <message>
        <source>Import &amp;Label...</source>
        <translation>导入标签(&amp;L)...</translation>
    </message>
    <message>
        <source>Import label (a mask on the CT&apos;s grid)</source>
        <translation>导入标签（CT 网格上的掩模）</translation>
    </message>
    <message>
        <source>Volumes (*.nii *.nii.gz *.nrrd *.nhdr *.mha *.mhd);;DICOM SEG or a mask series&apos; slice (*.dcm *.DCM *.IMA);;All files (*)</source>
        <translation>体数据 (*.nii *.nii.gz *.nrrd *.nhdr *.mha *.mhd);;DICOM SEG 或掩模序列的一层 (*.dcm *.DCM *.IMA);;所有文件 (*)</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>保存(&amp;S)</translation>
    </message>
    <message>
        <source>Save &amp;As...</source>
        <translation>另存为(&amp;A)...</translation>
    </message>
    <message>
        <source>Export &amp;Report...</source>
        <translation>导出报告(&amp;R)...</translation>
    </message>
    <message>
        <source>Ctrl+R</source>
        <translation>Ctrl+R</translation>
    </message>
    <message>
        <source>&amp;Close Window</source>
        <translation>关闭窗口(&amp;C)</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>退出(&amp;Q)</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>编辑(&amp;E)</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>撤销(&amp;U)</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>重做(&amp;R)</translation>
    </message>
    <message>
        <source>Re&amp;name Artifact...</source>
        <translation>重命名对象(&amp;N)...</translation>
    </message>
    <message>
        <source>Rename artifact</source>
        <translation>重命名对象</translation>
    </message>
    <message>
        <source>Name:</source>
        <translation>名称：</translation>
    </message>
    <message>
        <source>&amp;Delete Artifact</source>
        <translation>删除对象(&amp;D)</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>视图(&amp;V)</translation>
    </message>
    <message>
        <source>Window/Level: &amp;CTA</source>
        <translation>窗宽/窗位：CTA(&amp;C)</translation>
    </message>
    <message>
        <source>Window/Level: &amp;Soft Tissue</source>
        <translation>窗宽/窗位：软组织(&amp;S)</translation>
    </message>
    <message>
        <source>Window/Level: &amp;Bone</source>
        <translation>窗宽/窗位：骨(&amp;B)</translation>
    </message>
    <message>
        <source>Window/Level: &amp;Lung</source>
        <translation>窗宽/窗位：肺(&amp;L)</translation>
    </message>
    <message>
        <source>&amp;Reset Slice Views</source>
        <translation>重置切片视图(&amp;R)</translation>
    </message>
    <message>
        <source>Centre the volume and show it whole in the axial, coronal and sagittal views (R in a view)</source>
        <translation>使体数据居中，并在轴位、冠状位和矢状位视图中完整显示（在视图中按 R）</translation>
    </message>
    <message>
        <source>&amp;Link Slice Views</source>
        <translation>链接切片视图(&amp;L)</translation>
    </message>
    <message>
        <source>Linked, the slice views share the cursor and window/level</source>
        <translation>链接后，各切片视图共享光标和窗宽/窗位</translation>
    </message>
    <message>
        <source>Show &amp;Crosshair</source>
        <translation>显示十字线(&amp;C)</translation>
    </message>
    <message>
        <source>Right Drag &amp;Zooms (Slicer)</source>
        <translation>右键拖动缩放(&amp;Z)（Slicer）</translation>
    </message>
    <message>
        <source>Right drag in a slice view zooms instead of changing window/level (kept in the settings)</source>
        <translation>在切片视图中右键拖动时缩放，而不是改变窗宽/窗位（保存在设置中）</translation>
    </message>
    <message>
        <source>Thick Slab &amp;MIP</source>
        <translation>厚层 MIP(&amp;M)</translation>
    </message>
    <message>
        <source>Off (thin slice)</source>
        <translation>关闭（薄层）</translation>
    </message>
    <message>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <source>3D: &amp;Anterior View</source>
        <translation>3D：前视图(&amp;A)</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>帮助(&amp;H)</translation>
    </message>
    <message>
        <source>&amp;User Guide</source>
        <translation>用户指南(&amp;U)</translation>
    </message>
    <message>
        <source>&amp;Keyboard and Mouse</source>
        <translation>键盘与鼠标(&amp;K)</translation>
    </message>
    <message>
        <source>&amp;About VascuSim</source>
        <translation>关于 VascuSim(&amp;A)</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>语言(&amp;L)</translation>
    </message>
    <message>
        <source>System Language</source>
        <translation>系统语言</translation>
    </message>
    <message>
        <source>The language changes when VascuSim starts next.</source>
        <translation>语言将在 VascuSim 下次启动时更改。</translation>
    </message>
    <message>
        <source>About VascuSim</source>
        <translation>关于 VascuSim</translation>
    </message>
    <message>
        <source>&lt;h3&gt;VascuSim&lt;/h3&gt;&lt;p&gt;Patient-specific physics for vascular procedure planning.&lt;/p&gt;&lt;p&gt;Results support planning and need clinical judgement.&lt;/p&gt;&lt;table&gt;%1&lt;/table&gt;</source>
        <translation>&lt;h3&gt;VascuSim&lt;/h3&gt;&lt;p&gt;用于血管介入手术规划的患者特异性物理模拟。&lt;/p&gt;&lt;p&gt;结果仅辅助规划，需结合临床判断。&lt;/p&gt;&lt;table&gt;%1&lt;/table&gt;</translation>
    </message>
    <message>
        <source>&amp;Drug</source>
        <translation>药物(&amp;D)</translation>
    </message>
    <message>
        <source>Drug &amp;Delivery</source>
        <translation>药物输送(&amp;D)</translation>
    </message>
    <message>
        <source>&amp;Liver from Points</source>
        <translation>从点生成肝脏(&amp;L)</translation>
    </message>
    <message>
        <source>&amp;Tumour from Points</source>
        <translation>从点生成肿瘤(&amp;T)</translation>
    </message>
    <message>
        <source>Drug &amp;Parameters...</source>
        <translation>药物参数(&amp;P)...</translation>
    </message>
    <message>
        <source>Drug delivery parameters</source>
        <translation>药物输送参数</translation>
    </message>
    <message>
        <source>Drug delivery</source>
        <translation>药物输送</translation>
    </message>
    <message>
        <source>The network needs centerlines: run Skeleton &amp;&amp; Centerlines first.</source>
        <translation>网络需要中心线：请先运行“骨架与中心线”。</translation>
    </message>
    <message>
        <source>The tip needs three numbers (mm) and the tumour four (centre and radius).</source>
        <translation>尖端需要三个数（mm），肿瘤需要四个（中心和半径）。</translation>
    </message>
    <message>
        <source>The tumour&apos;s radius must be positive.</source>
        <translation>肿瘤半径必须为正数。</translation>
    </message>
    <message>
        <source>Control points are x, y, z in mm, separated by &apos;;&apos;.</source>
        <translation>控制点为以 mm 为单位的 x, y, z，用“;”分隔。</translation>
    </message>
    <message>
        <source>The tumour label is read with a liver label: choose the liver too.</source>
        <translation>肿瘤标签需与肝脏标签一起读取：请同时选择肝脏。</translation>
    </message>
    <message>
        <source>Feeders are corrected on a run with a liver label: choose the liver too.</source>
        <translation>供血支在带肝脏标签的运行上校正：请同时选择肝脏。</translation>
    </message>
    <message>
        <source>Drug flow</source>
        <translation>药物流量</translation>
    </message>
    <message>
        <source>Drug Delivery</source>
        <translation>药物输送</translation>
    </message>
    <message>
        <source>Drug delivery: %1 outlets, last reached after %2 s</source>
        <translation>药物输送：%1 个出口，%2 s 后到达最后一个</translation>
    </message>
    <message>
        <source>Tumour from points</source>
        <translation>从点生成肿瘤</translation>
    </message>
    <message>
        <source>Liver from points</source>
        <translation>从点生成肝脏</translation>
    </message>
    <message>
        <source>Place include points inside the %1 first (Vessels &gt; Segment from Points, on the MPR views), then grow it from them.</source>
        <translation>请先在%1内放置包含点（血管 &gt; 从点分割，在 MPR 视图上），然后从这些点生长。</translation>
    </message>
    <message>
        <source>tumour</source>
        <translation>肿瘤</translation>
    </message>
    <message>
        <source>liver</source>
        <translation>肝脏</translation>
    </message>
    <message>
        <source>A tumour grows within the liver: choose the liver label in the Drug Delivery dock first (or grow it: Drug &gt; Liver from Points).</source>
        <translation>肿瘤在肝脏内生长：请先在“药物输送”停靠窗中选择肝脏标签（或生成它：药物 &gt; 从点生成肝脏）。</translation>
    </message>
    <message>
        <source>%1 grown from %2 point(s): %3 ml; choose it as the %4 label in the Drug Delivery dock</source>
        <translation>由 %2 个点生长出%1：%3 ml；请在“药物输送”停靠窗中将其选为%4标签</translation>
    </message>
    <message>
        <source>tip</source>
        <translation>尖端</translation>
    </message>
    <message>
        <source>lesion %1</source>
        <translation>病灶 %1</translation>
    </message>
    <message>
        <source>feeder %1</source>
        <translation>供血支 %1</translation>
    </message>
    <message>
        <source>Chemoembolization from the tip: coverage grade %1, territory %2 ml, %3 feeder(s)</source>
        <translation>从尖端化疗栓塞：覆盖等级 %1，供血区域 %2 ml，%3 个供血支</translation>
    </message>
    <message>
        <source>F&amp;low</source>
        <translation>血流(&amp;L)</translation>
    </message>
    <message>
        <source>Blood &amp;Flow (SPH)</source>
        <translation>血流 (SPH)(&amp;F)</translation>
    </message>
    <message>
        <source>Needle &amp;Injection (SPH, Thesis Scenario a)</source>
        <translation>针头注射（SPH，论文情景 a）(&amp;I)</translation>
    </message>
    <message>
        <source>&amp;Wall Loads</source>
        <translation>管壁载荷(&amp;W)</translation>
    </message>
    <message>
        <source>Time-Averaged Wall &amp;Shear Stress</source>
        <translation>时间平均管壁剪切应力(&amp;S)</translation>
    </message>
    <message>
        <source>&amp;Oscillatory Shear Index</source>
        <translation>振荡剪切指数(&amp;O)</translation>
    </message>
    <message>
        <source>Mean Wall &amp;Pressure</source>
        <translation>平均管壁压力(&amp;P)</translation>
    </message>
    <message>
        <source>Blood Flow &amp;Parameters...</source>
        <translation>血流参数(&amp;P)...</translation>
    </message>
    <message>
        <source>Blood flow parameters</source>
        <translation>血流参数</translation>
    </message>
    <message>
        <source>Inlet, outlets, figures</source>
        <translation>入口、出口、数值</translation>
    </message>
    <message>
        <source>Needle injection</source>
        <translation>针头注射</translation>
    </message>
    <message>
        <source>SPH solver</source>
        <translation>SPH 求解器</translation>
    </message>
    <message>
        <source>Blood flow</source>
        <translation>血流</translation>
    </message>
    <message>
        <source>The vessel ends come from the centerlines: run Skeleton &amp;&amp; Centerlines first.</source>
        <translation>血管末端来自中心线：请先运行“骨架与中心线”。</translation>
    </message>
    <message>
        <source>Read these results with care: %1</source>
        <translation>请谨慎解读这些结果：%1</translation>
    </message>
    <message>
        <source>Blood flow: peak velocity ratio %1 at %2 mm along the centerline (mean ratio %3), pressure drop %4 mmHg</source>
        <translation>血流：峰值速度比 %1，位于沿中心线 %2 mm 处（平均比 %3），压降 %4 mmHg</translation>
    </message>
    <message>
        <source>Blood flow: no stenosis figures (%1)</source>
        <translation>血流：无狭窄数值（%1）</translation>
    </message>
    <message>
        <source>Needle injection: %1 ml in the vessel, %2 ml collected in the box at %3 s</source>
        <translation>针头注射：血管内 %1 ml，%3 s 时收集盒内 %2 ml</translation>
    </message>
    <message>
        <source>TAWSS (Pa)</source>
        <translation>TAWSS (Pa)</translation>
    </message>
    <message>
        <source>OSI (0-0.5)</source>
        <translation>OSI (0-0.5)</translation>
    </message>
    <message>
        <source>mean wall pressure (Pa)</source>
        <translation>平均管壁压力 (Pa)</translation>
    </message>
    <message>
        <source>Wall loads</source>
        <translation>管壁载荷</translation>
    </message>
    <message>
        <source>No wall loads yet: run Flow &gt; Blood Flow (SPH) long enough to reach its averaging window.</source>
        <translation>尚无管壁载荷：请让 血流 &gt; 血流 (SPH) 运行足够长，直到其平均时间窗。</translation>
    </message>
    <message>
        <source>, NOT CONVERGED</source>
        <translation>，未收敛</translation>
    </message>
    <message>
        <source>, STOPPED EARLY</source>
        <translation>，提前停止</translation>
    </message>
    <message>
        <source>, averaged over %1-%2 ms</source>
        <translation>，在 %1-%2 ms 上平均</translation>
    </message>
    <message>
        <source>, time-averaged</source>
        <translation>，时间平均</translation>
    </message>
    <message>
        <source>; grey: no value</source>
        <translation>；灰色：无值</translation>
    </message>
    <message>
        <source>Report</source>
        <translation>报告</translation>
    </message>
    <message>
        <source>No PDF viewer opened %1.</source>
        <translation>没有 PDF 查看器打开 %1。</translation>
    </message>
    <message>
        <source>Replace files</source>
        <translation>替换文件</translation>
    </message>
    <message>
        <source>These files exist already:
%1
Replace them?</source>
        <translation>这些文件已存在：
%1
替换它们吗？</translation>
    </message>
    <message>
        <source>Report written to %1</source>
        <translation>报告已写入 %1</translation>
    </message>
    <message>
        <source>Preparing the views</source>
        <translation>正在准备视图</translation>
    </message>
    <message>
        <source>Segment</source>
        <comment>a vessel segment (noun)</comment>
        <translation>段</translation>
    </message>
    <message>
        <source>The segment&apos;s anatomical name (double-click to rename) or its end nodes</source>
        <translation>段的解剖名称（双击重命名）或其端节点</translation>
    </message>
    <message>
        <source>Length (mm)</source>
        <translation>长度 (mm)</translation>
    </message>
    <message>
        <source>Length along the centerline (mm)</source>
        <translation>沿中心线的长度 (mm)</translation>
    </message>
    <message>
        <source>Start r (mm)</source>
        <translation>起点 r (mm)</translation>
    </message>
    <message>
        <source>Lumen radius at the segment&apos;s start (mm)</source>
        <translation>段起点的管腔半径 (mm)</translation>
    </message>
    <message>
        <source>End r (mm)</source>
        <translation>终点 r (mm)</translation>
    </message>
    <message>
        <source>Lumen radius at the segment&apos;s end (mm)</source>
        <translation>段终点的管腔半径 (mm)</translation>
    </message>
    <message>
        <source>Reference Ø (mm)</source>
        <translation>参考 Ø (mm)</translation>
    </message>
    <message>
        <source>Reference lumen diameter: the median equivalent diameter of the segment&apos;s sections (mm)</source>
        <translation>参考管腔直径：该段各截面等效直径的中位数 (mm)</translation>
    </message>
    <message>
        <source>Minimal Ø (mm)</source>
        <translation>最小 Ø (mm)</translation>
    </message>
    <message>
        <source>Minimal lumen diameter (equivalent) along the segment, in sections perpendicular to the centerline (mm)</source>
        <translation>沿该段在垂直于中心线的截面中的最小管腔直径（等效）(mm)</translation>
    </message>
    <message>
        <source>Stenosis (%)</source>
        <translation>狭窄 (%)</translation>
    </message>
    <message>
        <source>Diameter stenosis: 100 (1 - minimal / reference diameter) (%)</source>
        <translation>直径狭窄率：100 (1 - 最小 / 参考直径) (%)</translation>
    </message>
    <message>
        <source>Max Ø (mm)</source>
        <translation>最大 Ø (mm)</translation>
    </message>
    <message>
        <source>Largest lumen caliper width along the segment (mm); the AAA diameter outer wall to outer wall (SVS) is the sac&apos;s row</source>
        <translation>沿该段的最大管腔卡尺宽度 (mm)；外壁到外壁的 AAA 直径（SVS）见瘤囊一行</translation>
    </message>
    <message>
        <source>Name Segment</source>
        <translation>命名段</translation>
    </message>
    <message>
        <source>Anatomical name of the segment:</source>
        <translation>段的解剖名称：</translation>
    </message>
    <message>
        <source>Measurements</source>
        <translation>测量</translation>
    </message>
    <message>
        <source>Segment %1 (nodes %2-%3); double-click to rename</source>
        <translation>段 %1（节点 %2-%3）；双击重命名</translation>
    </message>
    <message>
        <source>AAA maximum diameter, outer wall to outer wall (SVS): %1 mm</source>
        <translation>AAA 最大直径，外壁到外壁（SVS）：%1 mm</translation>
    </message>
    <message>
        <source>Lumen diameter there (equivalent): %1 mm</source>
        <translation>该处管腔直径（等效）：%1 mm</translation>
    </message>
    <message>
        <source>Largest thrombus thickness: %1 mm</source>
        <translation>最大血栓厚度：%1 mm</translation>
    </message>
    <message>
        <source>Sac volume: %1 ml</source>
        <translation>瘤囊体积：%1 ml</translation>
    </message>
    <message>
        <source>Neck diameter (outer, at the lowest renal artery): %1 mm</source>
        <translation>瘤颈直径（外径，最低肾动脉处）：%1 mm</translation>
    </message>
    <message>
        <source>Neck length: %1 mm</source>
        <translation>瘤颈长度：%1 mm</translation>
    </message>
    <message>
        <source>Neck angulation: %1 degrees</source>
        <translation>瘤颈成角：%1 度</translation>
    </message>
    <message>
        <source>Right common iliac diameter (outer): %1 mm</source>
        <translation>右髂总动脉直径（外径）：%1 mm</translation>
    </message>
    <message>
        <source>Left common iliac diameter (outer): %1 mm</source>
        <translation>左髂总动脉直径（外径）：%1 mm</translation>
    </message>
    <message>
        <source>Wall thickness (assumed): %1 mm</source>
        <translation>管壁厚度（假设）：%1 mm</translation>
    </message>
    <message>
        <source>Maximum lumen diameter %1 mm (equivalent, perpendicular)</source>
        <translation>最大管腔直径 %1 mm（等效，垂直）</translation>
    </message>
    <message>
        <source>V&amp;essels</source>
        <translation>血管(&amp;E)</translation>
    </message>
    <message>
        <source>Segment from &amp;Points...</source>
        <translation>从点分割(&amp;P)...</translation>
    </message>
    <message>
        <source>&amp;Segment Vessels</source>
        <translation>分割血管(&amp;S)</translation>
    </message>
    <message>
        <source>Segment from the &amp;Cursor</source>
        <translation>从光标处分割(&amp;C)</translation>
    </message>
    <message>
        <source>S&amp;keleton and Centerlines</source>
        <translation>骨架与中心线(&amp;K)</translation>
    </message>
    <message>
        <source>AAA &amp;Sac (Outer Wall, Thrombus)</source>
        <translation>AAA 瘤囊（外壁、血栓）(&amp;S)</translation>
    </message>
    <message>
        <source>&amp;Along the Vessel (3D + CPR)</source>
        <translation>沿血管(&amp;A)（3D + CPR）</translation>
    </message>
    <message>
        <source>&amp;Edit Label (Brush)</source>
        <translation>编辑标签（画笔）(&amp;E)</translation>
    </message>
    <message>
        <source>&amp;Parameters...</source>
        <translation>参数(&amp;P)...</translation>
    </message>
    <message>
        <source>Vessel parameters</source>
        <translation>血管参数</translation>
    </message>
    <message>
        <source>Segmentation</source>
        <translation>分割</translation>
    </message>
    <message>
        <source>Segmentation from points</source>
        <translation>从点分割</translation>
    </message>
    <message>
        <source>Skeleton</source>
        <translation>骨架</translation>
    </message>
    <message>
        <source>Centerlines</source>
        <translation>中心线</translation>
    </message>
    <message>
        <source>The study has no CT image: import one first.</source>
        <translation>研究中没有 CT 图像：请先导入。</translation>
    </message>
    <message>
        <source>Segment vessels</source>
        <translation>分割血管</translation>
    </message>
    <message>
        <source>AAA sac</source>
        <translation>AAA 瘤囊</translation>
    </message>
    <message>
        <source>The study needs a CT image and an aortic lumen label: segment the aorta first.</source>
        <translation>研究需要 CT 图像和主动脉管腔标签：请先分割主动脉。</translation>
    </message>
    <message>
        <source>Skeleton and centerlines</source>
        <translation>骨架与中心线</translation>
    </message>
    <message>
        <source>Segmentation Points</source>
        <translation>分割点</translation>
    </message>
    <message>
        <source>Segment from points</source>
        <translation>从点分割</translation>
    </message>
    <message>
        <source>Place at least one include point inside the vessel (Place Include, then click in a slice view).</source>
        <translation>请至少在血管内放置一个包含点（放置包含点，然后在切片视图中点击）。</translation>
    </message>
    <message>
        <source>Segmented %1 ml (%2 leak(s) cut)%3</source>
        <translation>已分割 %1 ml（切除 %2 处泄漏）%3</translation>
    </message>
    <message>
        <source>, replacing the label of the run before</source>
        <translation>，替换上一次运行的标签</translation>
    </message>
    <message>
        <source>&amp;Wall</source>
        <translation>管壁(&amp;W)</translation>
    </message>
    <message>
        <source>Build &amp;Wall Mesh</source>
        <translation>构建管壁网格(&amp;W)</translation>
    </message>
    <message>
        <source>Wall Stress at &amp;Blood Pressure</source>
        <translation>血压下的管壁应力(&amp;B)</translation>
    </message>
    <message>
        <source>&amp;Interactive Protocol</source>
        <translation>交互方案(&amp;I)</translation>
    </message>
    <message>
        <source>Wall &amp;Parameters...</source>
        <translation>管壁参数(&amp;P)...</translation>
    </message>
    <message>
        <source>Wall parameters</source>
        <translation>管壁参数</translation>
    </message>
    <message>
        <source>Wall mesh</source>
        <translation>管壁网格</translation>
    </message>
    <message>
        <source>Wall mechanics</source>
        <translation>管壁力学</translation>
    </message>
    <message>
        <source>&amp;Research</source>
        <translation>研究(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Thesis Rupture Protocol (not physiological pressures)</source>
        <translation>论文破裂方案（非生理压力）(&amp;T)</translation>
    </message>
    <message>
        <source>The wall needs a vessel label and centerlines: run Segment and Skeleton &amp;&amp; Centerlines first.</source>
        <translation>管壁需要血管标签和中心线：请先运行“分割”和“骨架与中心线”。</translation>
    </message>
    <message>
        <source>The thrombus layer needs the AAA sac: run Vessels &gt; AAA Sac first, or set Thrombus layer to 0 in the wall mesh parameters.</source>
        <translation>血栓层需要 AAA 瘤囊：请先运行 血管 &gt; AAA 瘤囊，或在管壁网格参数中将血栓层设为 0。</translation>
    </message>
    <message>
        <source>Wall: %1 elements, smallest dihedral angle %2 deg</source>
        <translation>管壁：%1 个单元，最小二面角 %2 度</translation>
    </message>
    <message>
        <source>Build the wall mesh first (Wall &gt; Build Wall Mesh).</source>
        <translation>请先构建管壁网格（管壁 &gt; 构建管壁网格）。</translation>
    </message>
    <message>
        <source>Wall stress</source>
        <translation>管壁应力</translation>
    </message>
    <message>
        <source>Thesis rupture protocol</source>
        <translation>论文破裂方案</translation>
    </message>
    <message>
        <source>Peak wall stress in the sac %1 kPa (99th percentile)</source>
        <translation>瘤囊内峰值管壁应力 %1 kPa（第 99 百分位）</translation>
    </message>
    <message>
        <source>Highest wall stress %1 kPa (no sac measured)</source>
        <translation>最高管壁应力 %1 kPa（未测量瘤囊）</translation>
    </message>
    <message>
        <source>, rupture index %1</source>
        <translation>，破裂指数 %1</translation>
    </message>
    <message>
        <source>; no rupture index: give the patient&apos;s sex and family history</source>
        <translation>；无破裂指数：请给出患者的性别和家族史</translation>
    </message>
    <message>
        <source>von Mises (kPa), NOT CONVERGED</source>
        <translation>von Mises 应力 (kPa)，未收敛</translation>
    </message>
    <message>
        <source>von Mises (kPa), STOPPED EARLY</source>
        <translation>von Mises 应力 (kPa)，提前停止</translation>
    </message>
    <message>
        <source>von Mises (kPa)</source>
        <translation>von Mises 应力 (kPa)</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>播放</translation>
    </message>
    <message>
        <source>0 mmHg</source>
        <translation>0 mmHg</translation>
    </message>
    <message>
        <source>Tear at %1 MPa</source>
        <translation>在 %1 MPa 时撕裂</translation>
    </message>
    <message>
        <source>Pressure</source>
        <translation>压力</translation>
    </message>
    <message>
        <source>Drag the wall with the left button in the 3D view.</source>
        <translation>在 3D 视图中用左键拖动管壁。</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <source>%1 mmHg</source>
        <translation>%1 mmHg</translation>
    </message>
    <message>
        <source>%1 frames/s, peak von Mises %2 kPa</source>
        <translation>%1 帧/秒，峰值 von Mises 应力 %2 kPa</translation>
    </message>
    <message>
        <source>The simulation paused: %1</source>
        <translation>模拟已暂停：%1</translation>
    </message>
    <message>
        <source>Interactive Wall</source>
        <translation>交互式管壁</translation>
    </message>
    <message>
        <source>Loading run</source>
        <translation>正在加载运行</translation>
    </message>
    <message>
        <source>Click or drag to go to a frame</source>
        <translation>点击或拖动以转到某一帧</translation>
    </message>
    <message>
        <source>Run Player</source>
        <translation>运行播放器</translation>
    </message>
    <message>
        <source>Run Player: %1</source>
        <translation>运行播放器：%1</translation>
    </message>
    <message>
        <source>peak (fastest 5 %)</source>
        <translation>峰值（最快 5 %）</translation>
    </message>
    <message>
        <source>mean (flow rate / area)</source>
        <translation>平均（流量 / 面积）</translation>
    </message>
    <message>
        <source>mean pressure</source>
        <translation>平均压力</translation>
    </message>
    <message>
        <source>along the centerline from the inlet (mm)</source>
        <translation>沿中心线距入口 (mm)</translation>
    </message>
    <message>
        <source>velocity (m/s), time-averaged sections</source>
        <translation>速度 (m/s)，时间平均截面</translation>
    </message>
    <message>
        <source>pressure (Pa, gauge), time-averaged</source>
        <translation>压力（Pa，表压），时间平均</translation>
    </message>
    <message>
        <source>peak</source>
        <translation>峰值</translation>
    </message>
    <message>
        <source>median</source>
        <translation>中位数</translation>
    </message>
    <message>
        <source>segments</source>
        <translation>段</translation>
    </message>
    <message>
        <source>blood particles</source>
        <translation>血液粒子</translation>
    </message>
    <message>
        <source>voxels</source>
        <translation>体素</translation>
    </message>
    <message>
        <source>cells</source>
        <translation>单元</translation>
    </message>
    <message>
        <source>%1 over the %2 of each frame</source>
        <translation>每帧 %2 上的 %1</translation>
    </message>
    <message>
        <source>&amp;Layout</source>
        <translation>布局(&amp;L)</translation>
    </message>
    <message>
        <source>2 x 2</source>
        <translation>2 x 2</translation>
    </message>
    <message>
        <source>1 x 1 (the active view)</source>
        <translation>1 x 1（当前视图）</translation>
    </message>
    <message>
        <source>1 x 3 (axial, coronal, sagittal)</source>
        <translation>1 x 3（轴位、冠状位、矢状位）</translation>
    </message>
    <message>
        <source>3D + MPR</source>
        <translation>3D + MPR</translation>
    </message>
    <message>
        <source>3D + CPR (along the vessel)</source>
        <translation>3D + CPR（沿血管）</translation>
    </message>
    <message>
        <source>&amp;Capture</source>
        <translation>捕获(&amp;C)</translation>
    </message>
    <message>
        <source>Screenshot of the Active &amp;View</source>
        <translation>当前视图截图(&amp;V)</translation>
    </message>
    <message>
        <source>Ctrl+Shift+S</source>
        <comment>screenshot of the view</comment>
        <translation>Ctrl+Shift+S</translation>
    </message>
    <message>
        <source>Screenshot of the &amp;Window</source>
        <translation>窗口截图(&amp;W)</translation>
    </message>
    <message>
        <source>Movie of the 3D &amp;Rotation</source>
        <translation>3D 旋转影片(&amp;R)</translation>
    </message>
    <message>
        <source>Movie of the Played &amp;Run</source>
        <translation>已播放运行的影片(&amp;R)</translation>
    </message>
    <message>
        <source>Capture &amp;Folder...</source>
        <translation>捕获文件夹(&amp;F)...</translation>
    </message>
    <message>
        <source>Capture folder</source>
        <translation>捕获文件夹</translation>
    </message>
    <message>
        <source>Screenshot saved: %1</source>
        <translation>截图已保存：%1</translation>
    </message>
    <message>
        <source>Screenshot</source>
        <translation>截图</translation>
    </message>
    <message>
        <source>Movie</source>
        <translation>影片</translation>
    </message>
    <message>
        <source>Open a run first (double-click it in the study tree): the movie plays its frames.</source>
        <translation>请先打开一个运行（在研究树中双击）：影片播放其各帧。</translation>
    </message>
    <message>
        <source>Writing the movie frames...</source>
        <translation>正在写入影片帧...</translation>
    </message>
    <message>
        <source>Movie cancelled: its frames were removed</source>
        <translation>影片已取消：其帧已删除</translation>
    </message>
    <message>
        <source>Movie saved: %1 frames in %2%3</source>
        <translation>影片已保存：%1 帧，位于 %2%3</translation>
    </message>
    <message>
        <source>Ruler</source>
        <translation>标尺</translation>
    </message>
    <message>
        <source>Angle</source>
        <translation>角度</translation>
    </message>
    <message>
        <source>ROI</source>
        <translation>ROI</translation>
    </message>
    <message>
        <source>&amp;Measure</source>
        <translation>测量(&amp;M)</translation>
    </message>
    <message>
        <source>Measure</source>
        <translation>测量</translation>
    </message>
    <message>
        <source>&amp;Ruler</source>
        <translation>标尺(&amp;R)</translation>
    </message>
    <message>
        <source>Distance (mm): press at one end in a slice view, drag to the other, release</source>
        <translation>距离 (mm)：在切片视图中于一端按下，拖到另一端，松开</translation>
    </message>
    <message>
        <source>&amp;Angle</source>
        <translation>角度(&amp;A)</translation>
    </message>
    <message>
        <source>Angle (degrees): click the first arm&apos;s end, the vertex, then the second arm&apos;s end</source>
        <translation>角度（度）：依次点击第一条边的端点、顶点、第二条边的端点</translation>
    </message>
    <message>
        <source>Elliptical R&amp;OI</source>
        <translation>椭圆 ROI(&amp;O)</translation>
    </message>
    <message>
        <source>HU mean, SD and area (mm2) inside an ellipse: press at a corner of its box, drag, release</source>
        <translation>椭圆内的 HU 均值、标准差和面积 (mm2)：在其外框的一角按下，拖动，松开</translation>
    </message>
    <message>
        <source> (Escape drops a drawing; the tool stays until clicked again)</source>
        <translation>（Esc 放弃绘制；工具保持选中，直到再次点击）</translation>
    </message>
    <message>
        <source>&amp;Include the Selected Measurement in the Report</source>
        <translation>将所选测量纳入报告(&amp;I)</translation>
    </message>
    <message>
        <source>Measure %1</source>
        <translation>测量 %1</translation>
    </message>
    <message>
        <source>Include &quot;%1&quot; in the report</source>
        <translation>将“%1”纳入报告</translation>
    </message>
    <message>
        <source>Leave &quot;%1&quot; out of the report</source>
        <translation>将“%1”移出报告</translation>
    </message>
    <message>
        <source>Along the vessel</source>
        <translation>沿血管</translation>
    </message>
    <message>
        <source>The vessel view follows a centerline: run Skeleton &amp;&amp; Centerlines first.</source>
        <translation>血管视图沿中心线显示：请先运行“骨架与中心线”。</translation>
    </message>
    <message>
        <source>Virtual &amp;Endoscope</source>
        <translation>虚拟内窥镜(&amp;E)</translation>
    </message>
    <message>
        <source>A camera inside the lumen flying along a centerline, with focal length and focus</source>
        <translation>管腔内沿中心线飞行的相机，可调焦距和对焦</translation>
    </message>
    <message>
        <source>Virtual endoscope</source>
        <translation>虚拟内窥镜</translation>
    </message>
    <message>
        <source>The endoscope flies along a centerline: run Skeleton &amp;&amp; Centerlines first.</source>
        <translation>内窥镜沿中心线飞行：请先运行“骨架与中心线”。</translation>
    </message>
    <message>
        <source>Virtual Endoscope</source>
        <translation>虚拟内窥镜</translation>
    </message>
    <message>
        <source>Surgical &amp;Smoke (Illustrative)</source>
        <translation>手术烟雾（示意）(&amp;S)</translation>
    </message>
    <message>
        <source>&amp;Ball Drop (Thesis Demo)</source>
        <translation>落球（论文演示）(&amp;B)</translation>
    </message>
    <message>
        <source>&amp;Endoscopic Vessel Harvesting</source>
        <translation>内镜血管采集(&amp;E)</translation>
    </message>
    <message>
        <source>&amp;Liver Ablation with Suction</source>
        <translation>带抽吸的肝消融(&amp;L)</translation>
    </message>
    <message>
        <source>Surgical smoke</source>
        <translation>手术烟雾</translation>
    </message>
    <message>
        <source>The EVH tunnel is drawn around a vessel&apos;s centerline: run Skeleton &amp;&amp; Centerlines first.</source>
        <translation>EVH 隧道围绕血管中心线绘制：请先运行 骨架与中心线。</translation>
    </message>
    <message>
        <source>not reached</source>
        <translation>未达到</translation>
    </message>
    <message>
        <source>after %1 s</source>
        <translation>%1 s 后</translation>
    </message>
    <message>
        <source>Surgical smoke (illustrative): the endoscope&apos;s view 50 % obscured %1, 90 % %2; at most %3 % obscured</source>
        <translation>手术烟雾（示意）：内镜视野 50 % 被遮挡：%1，90 %：%2；最多 %3 % 被遮挡</translation>
    </message>
    <message>
        <source>Smoke &amp;Parameters...</source>
        <translation>烟雾参数(&amp;P)...</translation>
    </message>
    <message>
        <source>Surgical smoke parameters</source>
        <translation>手术烟雾参数</translation>
    </message>
    <message>
        <source>Ball drop</source>
        <translation>落球</translation>
    </message>
    <message>
        <source>Vessel harvesting</source>
        <translation>血管采集</translation>
    </message>
    <message>
        <source>Liver ablation</source>
        <translation>肝消融</translation>
    </message>
    <message>
        <source>Query/Retrieve (&amp;PACS)...</source>
        <translation>查询/获取 (&amp;PACS)...</translation>
    </message>
    <message>
        <source>Retrieve from PACS</source>
        <translation>从 PACS 获取</translation>
    </message>
    <message>
        <source>Open or create a study first: the retrieved CT is imported into it.</source>
        <translation>请先打开或创建一个研究：获取的 CT 将导入其中。</translation>
    </message>
    <message>
        <source>Retrieve %1 from PACS</source>
        <translation>从 PACS 获取 %1</translation>
    </message>
    <message>
        <source>Send to PAC&amp;S...</source>
        <translation>发送到 PAC&amp;S...</translation>
    </message>
    <message>
        <source>Send to PACS %1</source>
        <translation>发送到 PACS %1</translation>
    </message>
    <message>
        <source>Sent %1 objects to %2.</source>
        <translation>已向 %2 发送 %1 个对象。</translation>
    </message>
</context>
<context>
    <name>vsim::gui::PacsDialog</name>
    <message>
        <source>Query/Retrieve (PACS)</source>
        <translation>查询/获取 (PACS)</translation>
    </message>
    <message>
        <source>Patient ID</source>
        <translation>患者 ID</translation>
    </message>
    <message>
        <source>Description</source>
        <translation>描述</translation>
    </message>
    <message>
        <source>Accession</source>
        <translation>检查号</translation>
    </message>
    <message>
        <source>Modalities</source>
        <translation>模态</translation>
    </message>
    <message>
        <source>Choose or enter a PACS node, then Echo or Search.</source>
        <translation>选择或输入 PACS 节点，然后执行 Echo 或搜索。</translation>
    </message>
    <message>
        <source>Retrieve and Import</source>
        <translation>获取并导入</translation>
    </message>
    <message>
        <source>PACS node</source>
        <translation>PACS 节点</translation>
    </message>
    <message>
        <source>Saved:</source>
        <translation>已保存：</translation>
    </message>
    <message>
        <source>e.g. Radiology PACS</source>
        <translation>例如 放射科 PACS</translation>
    </message>
    <message>
        <source>Name:</source>
        <translation>名称：</translation>
    </message>
    <message>
        <source>AE title:</source>
        <translation>AE 标题：</translation>
    </message>
    <message>
        <source>Host:</source>
        <translation>主机：</translation>
    </message>
    <message>
        <source>Port:</source>
        <translation>端口：</translation>
    </message>
    <message>
        <source>Our AE title, as the PACS has it registered</source>
        <translation>PACS 中登记的我方 AE 标题</translation>
    </message>
    <message>
        <source>Our AE title:</source>
        <translation>我方 AE 标题：</translation>
    </message>
    <message>
        <source> s</source>
        <translation> 秒</translation>
    </message>
    <message>
        <source>Timeout:</source>
        <translation>超时：</translation>
    </message>
    <message>
        <source>empty: UUID-based UIDs (2.25...)</source>
        <translation>留空：基于 UUID 的 UID (2.25...)</translation>
    </message>
    <message>
        <source>The organisation&apos;s DICOM UID root for the reports and segmentations VascuSim makes</source>
        <translation>本机构用于 VascuSim 生成的报告和分割的 DICOM UID 根</translation>
    </message>
    <message>
        <source>UID root:</source>
        <translation>UID 根：</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>保存</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>删除</translation>
    </message>
    <message>
        <source>Echo</source>
        <translation>Echo</translation>
    </message>
    <message>
        <source>Test the connection (C-ECHO)</source>
        <translation>测试连接（C-ECHO）</translation>
    </message>
    <message>
        <source>e.g. DOE^J* (wildcards * and ?)</source>
        <translation>例如 DOE^J*（通配符 * 和 ?）</translation>
    </message>
    <message>
        <source>Patient name:</source>
        <translation>患者姓名：</translation>
    </message>
    <message>
        <source>Patient ID:</source>
        <translation>患者 ID：</translation>
    </message>
    <message>
        <source>YYYYMMDD</source>
        <translation>YYYYMMDD</translation>
    </message>
    <message>
        <source>to</source>
        <translation>至</translation>
    </message>
    <message>
        <source>Study date:</source>
        <translation>检查日期：</translation>
    </message>
    <message>
        <source>Modality:</source>
        <translation>模态：</translation>
    </message>
    <message>
        <source>Search</source>
        <translation>搜索</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <source>Give the node a name to save it.</source>
        <translation>请为节点命名后再保存。</translation>
    </message>
    <message>
        <source>Not saved: %1</source>
        <translation>未保存：%1</translation>
    </message>
    <message>
        <source>Saved %1.</source>
        <translation>已保存 %1。</translation>
    </message>
    <message>
        <source>Echo to %1...</source>
        <translation>向 %1 发送 Echo...</translation>
    </message>
    <message>
        <source>%1 answers the echo.</source>
        <translation>%1 响应了 Echo。</translation>
    </message>
    <message>
        <source>Echo failed: %1</source>
        <translation>Echo 失败：%1</translation>
    </message>
    <message>
        <source>A study date is YYYYMMDD (8 digits).</source>
        <translation>检查日期格式为 YYYYMMDD（8 位数字）。</translation>
    </message>
    <message>
        <source>Searching %1...</source>
        <translation>正在搜索 %1...</translation>
    </message>
    <message>
        <source>Search failed: %1</source>
        <translation>搜索失败：%1</translation>
    </message>
    <message>
        <source>%1, %2</source>
        <translation>%1，%2</translation>
    </message>
    <message>
        <source>Studies found: %1.</source>
        <translation>找到的研究：%1。</translation>
    </message>
    <message>
        <source>Patient / series</source>
        <translation>患者 / 序列</translation>
    </message>
    <message>
        <source>Date</source>
        <translation>日期</translation>
    </message>
    <message>
        <source>Count</source>
        <translation>数量</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Stop the echo or the query (C-CANCEL)</source>
        <translation>停止 Echo 或查询（C-CANCEL）</translation>
    </message>
    <message>
        <source>Fetch the selected study or series (C-GET) and import its CT into the open study</source>
        <translation>获取所选研究或序列（C-GET）并将其 CT 导入当前打开的研究</translation>
    </message>
    <message>
        <source>DICOM TLS</source>
        <translation>DICOM TLS</translation>
    </message>
    <message>
        <source>Encrypt the connection (DICOM TLS, BCP 195); the PACS must prove itself with a trusted certificate</source>
        <translation>加密连接（DICOM TLS，BCP 195）；PACS 必须以受信任的证书证明身份</translation>
    </message>
    <message>
        <source>PEM files (*.pem *.crt *.cer *.key);;All files (*)</source>
        <translation>PEM 文件 (*.pem *.crt *.cer *.key);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Trusted certificates:</source>
        <translation>受信任证书：</translation>
    </message>
    <message>
        <source>The PACS&apos;s certificate or its authority&apos;s (PEM)</source>
        <translation>PACS 的证书或其证书颁发机构的证书（PEM）</translation>
    </message>
    <message>
        <source>Our certificate:</source>
        <translation>我方证书：</translation>
    </message>
    <message>
        <source>Ours, for a PACS that requires one (PEM; optional)</source>
        <translation>我方证书，供要求证书的 PACS 使用（PEM；可选）</translation>
    </message>
    <message>
        <source>Our private key:</source>
        <translation>我方私钥：</translation>
    </message>
    <message>
        <source>The private key of our certificate (PEM, not encrypted)</source>
        <translation>我方证书的私钥（PEM，未加密）</translation>
    </message>
    <message>
        <source>Find</source>
        <translation>查找</translation>
    </message>
    <message>
        <source>Studies</source>
        <translation>研究</translation>
    </message>
    <message>
        <source>Patients</source>
        <translation>患者</translation>
    </message>
    <message>
        <source>List studies, or patients whose studies open below them; a study opens onto its series</source>
        <translation>列出研究，或列出患者（其研究在其下展开）；研究展开后显示其序列</translation>
    </message>
    <message>
        <source>List:</source>
        <translation>列出：</translation>
    </message>
    <message>
        <source>Cancelled.</source>
        <translation>已取消。</translation>
    </message>
    <message>
        <source>series</source>
        <translation>个序列</translation>
    </message>
    <message>
        <source>Patients found: %1.</source>
        <translation>找到的患者：%1。</translation>
    </message>
    <message>
        <source>born %1</source>
        <translation>出生于 %1</translation>
    </message>
    <message>
        <source>studies</source>
        <translation>项研究</translation>
    </message>
    <message>
        <source>Wait for the running query, or Cancel it, then open this row again.</source>
        <translation>请等待正在进行的查询或将其取消，然后再次展开此行。</translation>
    </message>
    <message>
        <source>Finding the studies of %1...</source>
        <translation>正在查找 %1 的研究...</translation>
    </message>
    <message>
        <source>Finding the series of %1...</source>
        <translation>正在查找 %1 的序列...</translation>
    </message>
    <message>
        <source>%1 #%2</source>
        <translation>%1 #%2</translation>
    </message>
    <message>
        <source>images</source>
        <translation>幅图像</translation>
    </message>
    <message>
        <source>Nothing found below this row.</source>
        <translation>此行下未找到任何内容。</translation>
    </message>
    <message>
        <source>Found: %1.</source>
        <translation>找到：%1。</translation>
    </message>
    <message>
        <source>%1 of %2, %3</source>
        <translation>%2 的 %1，%3</translation>
    </message>
</context>
<context>
    <name>vsim::gui::PacsSendDialog</name>
    <message>
        <source>Send to PACS</source>
        <translation>发送到 PACS</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <source>PACS node:</source>
        <translation>PACS 节点：</translation>
    </message>
    <message>
        <source>No PACS node is saved: add one in File &gt; Query/Retrieve (PACS).</source>
        <translation>尚未保存 PACS 节点：请在 文件 &gt; 查询/获取 (PACS) 中添加。</translation>
    </message>
    <message>
        <source>%1: none in the study</source>
        <translation>%1：研究中没有</translation>
    </message>
    <message>
        <source>%1: %2 (%3)</source>
        <translation>%1：%2（%3）</translation>
    </message>
    <message>
        <source>Newest report as a DICOM Encapsulated PDF</source>
        <translation>最新报告，作为 DICOM 封装 PDF</translation>
    </message>
    <message>
        <source>Newest label as a DICOM SEG</source>
        <translation>最新标签，作为 DICOM SEG</translation>
    </message>
    <message>
        <source>Do not send it (never into the patient&apos;s study)</source>
        <translation>不发送（绝不存入患者的研究）</translation>
    </message>
    <message>
        <source>Send it as a new anonymized study</source>
        <translation>作为新的匿名研究发送</translation>
    </message>
    <message>
        <source>An anonymized report:</source>
        <translation>匿名报告：</translation>
    </message>
    <message>
        <source>The objects go into the patient&apos;s study, referencing the CT series, under the UID root of Query/Retrieve.</source>
        <translation>这些对象存入患者的研究，引用 CT 序列，使用 查询/获取 中的 UID 根。</translation>
    </message>
    <message>
        <source>Send</source>
        <translation>发送</translation>
    </message>
</context>
<context>
    <name>vsim::gui::ParameterForm</name>
    <message>
        <source>%1 to %2%3, default %4%3</source>
        <translation>%1 至 %2%3，默认 %4%3</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>自动</translation>
    </message>
    <message>
        <source>Chosen for the vessel when the run starts (recorded in its provenance); untick to give this value, the default included.</source>
        <translation>运行开始时按血管选定（记录在其来源信息中）；取消勾选即采用此值，包括默认值。</translation>
    </message>
</context>
<context>
    <name>vsim::gui::ReportExportDialog</name>
    <message>
        <source>Export Report</source>
        <translation>导出报告</translation>
    </message>
    <message>
        <source>Browse...</source>
        <translation>浏览...</translation>
    </message>
    <message>
        <source>Report</source>
        <translation>报告</translation>
    </message>
    <message>
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
    <message>
        <source>A4</source>
        <translation>A4</translation>
    </message>
    <message>
        <source>Letter</source>
        <translation>Letter</translation>
    </message>
    <message>
        <source>Anonymize (no patient name, ID, birth date or institution)</source>
        <translation>匿名化（不含患者姓名、ID、出生日期或机构）</translation>
    </message>
    <message>
        <source>Also as DICOM Encapsulated PDF (a new series of the study)</source>
        <translation>同时作为 DICOM 封装 PDF（研究的新序列）</translation>
    </message>
    <message>
        <source>Also the metrics as CSV and JSON</source>
        <translation>同时导出 CSV 和 JSON 格式的指标</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>导出</translation>
    </message>
    <message>
        <source>PDF file:</source>
        <translation>PDF 文件：</translation>
    </message>
    <message>
        <source>Paper:</source>
        <translation>纸张：</translation>
    </message>
    <message>
        <source>The language of the report&apos;s texts and numbers; the workstation&apos;s by default</source>
        <translation>报告文本和数字所用的语言；默认与工作站一致</translation>
    </message>
    <message>
        <source>Language:</source>
        <translation>语言：</translation>
    </message>
    <message>
        <source>Run the solvers&apos; validation cases into the report (seconds to a minute)</source>
        <translation>运行求解器的验证算例并写入报告（数秒至一分钟）</translation>
    </message>
</context>
<context>
    <name>vsim::gui::RunPlayer</name>
    <message>
        <source>Loop</source>
        <translation>循环</translation>
    </message>
    <message>
        <source>Range per frame</source>
        <translation>每帧范围</translation>
    </message>
    <message>
        <source>Previous frame</source>
        <translation>上一帧</translation>
    </message>
    <message>
        <source>Next frame</source>
        <translation>下一帧</translation>
    </message>
    <message>
        <source>Play / pause</source>
        <translation>播放 / 暂停</translation>
    </message>
    <message>
        <source>Playback speed (1x = %1 frames per second)</source>
        <translation>播放速度（1x = 每秒 %1 帧）</translation>
    </message>
    <message>
        <source>The field the frames are coloured by</source>
        <translation>用于给帧着色的场</translation>
    </message>
    <message>
        <source>Scale the legend to each frame instead of the whole run</source>
        <translation>按每一帧而非整个运行缩放图例</translation>
    </message>
    <message>
        <source>no frames</source>
        <translation>无帧</translation>
    </message>
    <message>
        <source>frame %1 / %2, %3 %4 %5</source>
        <translation>帧 %1 / %2，%3 %4 %5</translation>
    </message>
    <message>
        <source>time</source>
        <translation>时间</translation>
    </message>
    <message>
        <source>pressure</source>
        <translation>压力</translation>
    </message>
</context>
<context>
    <name>vsim::gui::SegmentationPointsPanel</name>
    <message>
        <source>Aorta (with its branches)</source>
        <translation>主动脉（含分支）</translation>
    </message>
    <message>
        <source>Hepatic arteries</source>
        <translation>肝动脉</translation>
    </message>
    <message>
        <source>All vessels from the points</source>
        <translation>从各点出发的所有血管</translation>
    </message>
    <message>
        <source>Aorta: every aortic segment with its branches to a length (no point needed: the abdominal aorta is found). Hepatic: a point in the aorta and one in the hepatic artery. All: every contrast vessel connected to the points, up to the path length.</source>
        <translation>主动脉：每个主动脉段及其分支至一定长度（无需点：自动找到腹主动脉）。肝动脉：主动脉内一点和肝动脉内一点。所有：与各点相连的每条造影血管，直至路径长度。</translation>
    </message>
    <message>
        <source>Target</source>
        <translation>目标</translation>
    </message>
    <message>
        <source>target&apos;s default</source>
        <translation>目标默认值</translation>
    </message>
    <message>
        <source>Path length followed from the include points (0: aorta 1000 mm, hepatic 250 mm, all 150 mm)</source>
        <translation>从包含点出发追踪的路径长度（0：主动脉 1000 mm，肝动脉 250 mm，所有 150 mm）</translation>
    </message>
    <message>
        <source>Path length</source>
        <translation>路径长度</translation>
    </message>
    <message>
        <source>Place Include</source>
        <translation>放置包含点</translation>
    </message>
    <message>
        <source>Place Exclude</source>
        <translation>放置排除点</translation>
    </message>
    <message>
        <source>Click inside the vessel in any slice view to add an include point (drag a point to move it)</source>
        <translation>在任一切片视图中点击血管内部以添加包含点（拖动点可移动它）</translation>
    </message>
    <message>
        <source>Click in what must stay out (heart chamber, vein, kidney, bone) to add an exclude point</source>
        <translation>点击必须排除的结构（心腔、静脉、肾脏、骨骼）以添加排除点</translation>
    </message>
    <message>
        <source>Place Stop</source>
        <translation>放置停止面</translation>
    </message>
    <message>
        <source>Click in a slice view where the vessel must end: a stop plane in that view&apos;s plane through the point; the fronts do not cross it away from the include points</source>
        <translation>在切片视图中点击血管必须终止之处：过该点、位于该视图平面内的停止面；波前不会越过它离开包含点</translation>
    </message>
    <message>
        <source>Point</source>
        <translation>点</translation>
    </message>
    <message>
        <source>x (mm)</source>
        <translation>x (mm)</translation>
    </message>
    <message>
        <source>y (mm)</source>
        <translation>y (mm)</translation>
    </message>
    <message>
        <source>z (mm)</source>
        <translation>z (mm)</translation>
    </message>
    <message>
        <source>+N include point, xN exclude point, |N stop plane (its normal in the tag&apos;s tooltip)</source>
        <translation>+N 包含点，xN 排除点，|N 停止面（其法向见标记的提示）</translation>
    </message>
    <message>
        <source>Patient frame (LPS), mm</source>
        <translation>患者坐标系（LPS），mm</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>移除</translation>
    </message>
    <message>
        <source>Remove the selected point</source>
        <translation>移除所选的点</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>清除</translation>
    </message>
    <message>
        <source>Segment from the points (a re-run replaces the label of the run before)</source>
        <translation>从各点分割（重新运行将替换上一次运行的标签）</translation>
    </message>
    <message>
        <source>Re-run when a point moves</source>
        <translation>点移动时重新运行</translation>
    </message>
    <message>
        <source>Stop plane, normal (%1, %2, %3) towards the side the fronts do not enter</source>
        <translation>停止面，法向 (%1, %2, %3)，指向波前不进入的一侧</translation>
    </message>
    <message>
        <source>Segment</source>
        <comment>verb: segment the vessels</comment>
        <translation>分割</translation>
    </message>
</context>
<context>
    <name>vsim::gui::VesselViewPanel</name>
    <message>
        <source>The centerline segment shown along its length</source>
        <translation>沿其长度显示的中心线段</translation>
    </message>
    <message>
        <source>Rotation of the curved reformation about the centerline (degrees)</source>
        <translation>曲面重建绕中心线的旋转（度）</translation>
    </message>
    <message>
        <source>distance along the centerline (mm)</source>
        <translation>沿中心线的距离 (mm)</translation>
    </message>
    <message>
        <source>lumen diameter (mm)</source>
        <translation>管腔直径 (mm)</translation>
    </message>
    <message>
        <source>Segment</source>
        <translation>段</translation>
    </message>
    <message>
        <source>Rotation</source>
        <translation>旋转</translation>
    </message>
    <message>
        <source>lumen equivalent diameter (measured sections)</source>
        <translation>管腔等效直径（测量截面）</translation>
    </message>
    <message>
        <source>lumen diameter (2 x the centerline&apos;s radius: reads low)</source>
        <translation>管腔直径（中心线半径的 2 倍：偏低）</translation>
    </message>
    <message>
        <source>Straightened CPR, %1 deg
%2 mm of centerline</source>
        <translation>拉直 CPR，%1 度
中心线 %2 mm</translation>
    </message>
    <message>
        <source>Perpendicular to the centerline at %1 mm
lumen %2 mm (circle: %3)</source>
        <translation>在 %1 mm 处垂直于中心线
管腔 %2 mm（圆：%3）</translation>
    </message>
    <message>
        <source>equivalent diameter of the measured section</source>
        <translation>测量截面的等效直径</translation>
    </message>
    <message>
        <source>2 x the centerline&apos;s radius, which reads low; run the measurements</source>
        <translation>中心线半径的 2 倍，偏低；请运行测量</translation>
    </message>
    <message>
        <source>outer wall %1 mm (yellow: the largest caliper of the sac&apos;s labels here)</source>
        <translation>外壁 %1 mm（黄色：此处瘤囊标签的最大卡尺宽度）</translation>
    </message>
    <message>
        <source>segment %1</source>
        <translation>段 %1</translation>
    </message>
    <message>
        <source>%1 (%2 mm)</source>
        <translation>%1（%2 mm）</translation>
    </message>
    <message>
        <source>%1 to %2 (%3 mm)</source>
        <translation>%1 至 %2（%3 mm）</translation>
    </message>
</context>
<context>
    <name>vsim::gui::WorkflowChecklist</name>
    <message>
        <source>Import a CT angiography series (DICOM folder or volume file).</source>
        <translation>导入 CT 血管造影序列（DICOM 文件夹或体数据文件）。</translation>
    </message>
    <message>
        <source>Segment the contrast-filled vessel lumen (automatic seed).</source>
        <translation>分割充盈造影剂的血管管腔（自动种子）。</translation>
    </message>
    <message>
        <source>Skeleton (VDSM) and centerlines of the lumen, with diameters in mm.</source>
        <translation>管腔的骨架（VDSM）和中心线，直径以 mm 计。</translation>
    </message>
    <message>
        <source>Tetrahedral wall mesh around the lumen (wall and thrombus thickness in mm).</source>
        <translation>管腔周围的四面体管壁网格（管壁和血栓厚度以 mm 计）。</translation>
    </message>
    <message>
        <source>Wall stress (kPa) at physiological blood pressure, converged or marked so.</source>
        <translation>生理血压下的管壁应力 (kPa)，已收敛或有相应标记。</translation>
    </message>
    <message>
        <source>Blood flow (SPH): velocity ratios and wall pressure along the centerline.</source>
        <translation>血流 (SPH)：沿中心线的速度比和管壁压力。</translation>
    </message>
    <message>
        <source>Drug delivery: perfused territory, tumour coverage and feeders for the catheter tip of the Drug Delivery dock.</source>
        <translation>药物输送：“药物输送”停靠窗中导管尖端的灌注区域、肿瘤覆盖和供血支。</translation>
    </message>
    <message>
        <source>Export the PDF report of the study&apos;s results.</source>
        <translation>导出研究结果的 PDF 报告。</translation>
    </message>
    <message>
        <source>Import</source>
        <translation>导入</translation>
    </message>
    <message>
        <source>Skeleton &amp; Centerlines</source>
        <translation>骨架与中心线</translation>
    </message>
    <message>
        <source>Wall Mesh</source>
        <translation>管壁网格</translation>
    </message>
    <message>
        <source>Wall Stress</source>
        <translation>管壁应力</translation>
    </message>
    <message>
        <source>Blood Flow</source>
        <translation>血流</translation>
    </message>
    <message>
        <source>Drug Delivery</source>
        <translation>药物输送</translation>
    </message>
    <message>
        <source>Report</source>
        <translation>报告</translation>
    </message>
    <message>
        <source>not run</source>
        <translation>未运行</translation>
    </message>
    <message>
        <source>done: %1</source>
        <translation>完成：%1</translation>
    </message>
    <message>
        <source>stale: %1 was made from %2, which %3 has replaced since; run the step again</source>
        <translation>过期：%1 由 %2 生成，而 %3 此后已替换了它；请重新运行此步骤</translation>
    </message>
    <message>
        <source>done</source>
        <translation>完成</translation>
    </message>
    <message>
        <source>stale</source>
        <translation>过期</translation>
    </message>
    <message>
        <source>%1  (%2)</source>
        <translation>%1  (%2)</translation>
    </message>
    <message>
        <source>State: %1</source>
        <translation>状态：%1</translation>
    </message>
    <message>
        <source>Click to run.</source>
        <translation>点击以运行。</translation>
    </message>
    <message>
        <source>Segment</source>
        <comment>verb: segment the vessels</comment>
        <translation>分割</translation>
    </message>
    <message>
        <source>Surgical smoke (illustrative): the liver-ablation scene with its suction and the endoscope&apos;s obscuration over time; Flow &gt; Surgical Smoke has the other scenes.</source>
        <translation>手术烟雾（示意）：带抽吸的肝消融场景及内镜视野随时间的遮挡；其他场景见 血流 &gt; 手术烟雾。</translation>
    </message>
    <message>
        <source>Surgical Smoke</source>
        <translation>手术烟雾</translation>
    </message>
</context>
<context>
    <name>vsim::imaging::AneurysmSac</name>
    <message>
        <source>largest outer-wall to outer-wall caliper perpendicular to the centerline of the outer contour, thrombus and wall included (SVS 2018)</source>
        <translation>垂直于外轮廓中心线的最大外壁至外壁卡尺距离，包括血栓和血管壁（SVS 2018）</translation>
    </message>
    <message>
        <source>patient position (LPS) of the centre of that cross-section</source>
        <translation>该截面中心的患者位置（LPS）</translation>
    </message>
    <message>
        <source>equivalent diameter of the contrast lumen&apos;s perpendicular cross-section there</source>
        <translation>该处造影管腔垂直截面的等效直径</translation>
    </message>
    <message>
        <source>outer diameter perpendicular to the centerline at the origin of the lowest renal artery (the median 3 to 8 mm below it, clear of the branch; without the renal arteries in the label: the narrowest within 80 mm above the widest section)</source>
        <translation>最低肾动脉开口处垂直于中心线的外径（取其下方 3 至 8 mm 的中位数，避开分支；标签中无肾动脉时：最宽截面上方 80 mm 内的最窄处）</translation>
    </message>
    <message>
        <source>centerline length from the lowest renal artery&apos;s origin to the start of the sac</source>
        <translation>最低肾动脉开口至瘤囊起点的中心线长度</translation>
    </message>
    <message>
        <source>angle between the neck axis (lowest renal artery to the sac&apos;s start) and the sac axis (the sac&apos;s start to its end)</source>
        <translation>瘤颈轴（最低肾动脉至瘤囊起点）与瘤囊轴（瘤囊起点至终点）之间的夹角</translation>
    </message>
    <message>
        <source>patient position (LPS z) of the lowest renal artery&apos;s origin</source>
        <translation>最低肾动脉开口的患者位置（LPS z）</translation>
    </message>
    <message>
        <source>outer diameter of the left common iliac artery perpendicular to its centerline: the median 10 to 40 mm below the crotch</source>
        <translation>左髂总动脉垂直于其中心线的外径：分叉下方 10 至 40 mm 的中位数</translation>
    </message>
    <message>
        <source>outer diameter of the right common iliac artery perpendicular to its centerline: the median 10 to 40 mm below the crotch</source>
        <translation>右髂总动脉垂直于其中心线的外径：分叉下方 10 至 40 mm 的中位数</translation>
    </message>
    <message>
        <source>1.5 x the neck diameter (30 mm without a neck)</source>
        <translation>1.5 倍瘤颈直径（无瘤颈时为 30 mm）</translation>
    </message>
    <message>
        <source>assumed, not measured: the wall is that shell inside the outer contour</source>
        <translation>假定值，未测量：血管壁为外轮廓内侧的这一壳层</translation>
    </message>
    <message>
        <source>volume inside the outer contour between the perpendicular planes at the sac&apos;s ends</source>
        <translation>瘤囊两端垂直平面之间外轮廓内的容积</translation>
    </message>
    <message>
        <source>centerline length of the sac (outer diameter over the threshold, contiguous)</source>
        <translation>瘤囊的中心线长度（外径超过阈值的连续段）</translation>
    </message>
    <message>
        <source>largest distance from the lumen to the wall&apos;s inner surface along the rays of an axial section, within the sac</source>
        <translation>瘤囊内沿轴位截面射线从管腔到血管壁内表面的最大距离</translation>
    </message>
</context>
<context>
    <name>vsim::viz::SliceView</name>
    <message>
        <source>W %1  L %2</source>
        <translation>窗宽 %1  窗位 %2</translation>
    </message>
    <message>
        <source>MIP slab %1 mm</source>
        <translation>MIP 厚层 %1 mm</translation>
    </message>
    <message>
        <source>Im %1/%2  %3 = %4 mm</source>
        <translation>图像 %1/%2  %3 = %4 mm</translation>
    </message>
    <message>
        <source>(%1, %2, %3) mm</source>
        <translation>(%1, %2, %3) mm</translation>
    </message>
    <message>
        <source>%1 HU</source>
        <translation>%1 HU</translation>
    </message>
</context>
</TS>
